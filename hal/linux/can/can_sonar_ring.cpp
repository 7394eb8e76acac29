// SPDX-License-Identifier: GPL-3.0-or-later
// The CAN sonar ring: liveness by heartbeat, NMT start, one outstanding firing per node, faulty transducers withheld.
#include "hal/linux/can/can_sonar_ring.hpp"

#include "hal/linux/can/sonar_frames.hpp"

namespace robuter::hal::can {

using namespace cia402;

namespace {
constexpr std::int64_t kStartRepeatUs = 100'000;  // NMT start repeated at most this often, µs
constexpr std::int64_t kLostGraceUs = 100'000;    // a firing unanswered this long past its time-out is lost, µs
}  // namespace

CanSonarRing::CanSonarRing(FrameTransport& bus, std::uint8_t node_base, std::uint32_t heartbeat_timeout_ms)
    : bus_(bus), base_(node_base), timeout_us_(static_cast<std::int64_t>(heartbeat_timeout_ms) * 1000) {}

int CanSonarRing::channel_of(std::uint8_t id) const {
  if (id < base_ || id >= base_ + kChannels) return -1;
  return id - base_;
}

void CanSonarRing::configure(std::uint32_t timeout_ms, std::uint32_t sound_speed_m_s) {
  echo_timeout_ms_ = timeout_ms;
  sound_speed_ = sound_speed_m_s;
}

bool CanSonarRing::alive(int node) const {
  if (node < 0 || node >= kChannels) return false;
  const Channel& c = ch_[static_cast<std::size_t>(node)];
  return c.heard_us >= 0 && now_us_ - c.heard_us <= timeout_us_ && c.nmt == NmtState::operational;
}

// Busy while a firing is outstanding, unless it is overdue (lost: the scanner has moved on).
// The fire frame carries the firing's own time-out: the configured one, or a shorter one.
bool CanSonarRing::fire(int node, std::uint8_t mask, std::uint32_t timeout_ms) {
  if (!alive(node)) return false;
  Channel& c = ch_[static_cast<std::size_t>(node)];
  const std::int64_t due = c.fired_us + static_cast<std::int64_t>(c.timeout_ms) * 1000 + kLostGraceUs;
  if (c.pending && now_us_ < due) return false;
  const std::uint32_t t = timeout_ms > 0 && timeout_ms < echo_timeout_ms_ ? timeout_ms : echo_timeout_ms_;
  const auto id = static_cast<std::uint8_t>(base_ + node);
  if (!bus_.send(sonar::fire(id, mask, static_cast<std::uint16_t>(t), static_cast<std::uint16_t>(sound_speed_))))
    return false;
  bus_.flush();  // fired now, not at the backend's next activation
  c.pending = true;
  c.ready = false;
  c.fired_us = now_us_;
  c.mask = mask;
  c.timeout_ms = t;
  return true;
}

// A firing that included a faulty transducer never reads: the scanner drops the node and the
// emergency gate holds for lack of data instead of taking "no echo" for a clear way.
bool CanSonarRing::read(int node, NodeRanges& out) {
  if (node < 0 || node >= kChannels) return false;
  Channel& c = ch_[static_cast<std::size_t>(node)];
  if (!c.pending || !c.ready) return false;
  if (c.faulty & c.mask) return false;
  out = c.mm;
  c.pending = false;
  c.ready = false;
  return true;
}

void CanSonarRing::start(std::int64_t now_us) {
  now_us_ = now_us;
  for (auto& c : ch_) c = Channel{};
}

bool CanSonarRing::on_frame(const can_frame& f, std::int64_t now_us) {
  now_us_ = now_us;
  NmtState nmt{};
  if (const int n = channel_of(node_of(f, kHeartbeat)); n >= 0 && parse_heartbeat(f, nmt)) {
    Channel& c = ch_[static_cast<std::size_t>(n)];
    c.heard_us = now_us;
    c.nmt = nmt;
    if (nmt != NmtState::operational) c.pending = false;  // rebooted or stopped: the firing is gone
    return true;
  }
  std::uint8_t faulty = 0, flags = 0;
  if (const int n = channel_of(node_of(f, sonar::kStatus)); n >= 0 && sonar::parse_status(f, faulty, flags)) {
    ch_[static_cast<std::size_t>(n)].faulty = faulty;
    return true;
  }
  NodeRanges mm{};
  if (const int n = channel_of(node_of(f, sonar::kRanges)); n >= 0 && sonar::parse_ranges(f, mm)) {
    Channel& c = ch_[static_cast<std::size_t>(n)];
    if (c.pending) {
      for (std::size_t i = 0; i < mm.size(); ++i) c.mm[i] = ((c.mask >> i) & 1u) ? mm[i] : 0;
      c.ready = true;
    }
    return true;
  }
  return false;
}

void CanSonarRing::poll(std::int64_t now_us) {
  now_us_ = now_us;
  for (int n = 0; n < kChannels; ++n) {
    Channel& c = ch_[static_cast<std::size_t>(n)];
    if (c.heard_us < 0 || now_us - c.heard_us > timeout_us_ || c.nmt == NmtState::operational) continue;
    if (c.start_sent_us >= 0 && now_us - c.start_sent_us < kStartRepeatUs) continue;
    if (bus_.send(nmt(NmtCommand::start, static_cast<std::uint8_t>(base_ + n)))) c.start_sent_us = now_us;
  }
}

}  // namespace robuter::hal::can
