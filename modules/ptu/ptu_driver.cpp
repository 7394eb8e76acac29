// SPDX-License-Identifier: GPL-3.0-or-later
// The pan-tilt driver: start-up sequence, sweep between the ends, position polling, firing.
#include "modules/ptu/ptu_driver.hpp"

#include <algorithm>
#include <cmath>

namespace robuter::ptu {

PtuDriver::PtuDriver(hal::ByteStream* stream, hal::SonarRing& ring, const PtuSettings& s)
    : stream_(stream), ring_(ring), s_(s), target_(s.min_position) {
  scan_.fitted = stream_ != nullptr;
}

void PtuDriver::start(std::uint64_t tick) {
  if (state_ == DriverState::starting || state_ == DriverState::scanning) return;
  // Why reopen here: a start is the operator's retry (Ap), so a replugged unit is found again.
  if (stream_ == nullptr || (!stream_->connected() && !stream_->reopen())) {
    fail(stream_ == nullptr ? DriverFault::no_unit : DriverFault::lost);
    return;
  }
  fault_ = DriverFault::none;
  failures_ = 0;
  have_pos_ = false;
  have_velocity_ = false;
  velocity_ = accel_ = 0.0;
  reverse_due_ = false;
  echo_pending_ = false;
  last_sector_ = -1;
  lines_.clear();
  last_send_ = 0;
  if (fault_ == DriverFault::lost) set_up_ = false;  // a replugged unit may have been reset
  // Why not re-run the start-up when resuming: the unit keeps its settings; polling finds it.
  state_ = set_up_ ? DriverState::scanning : DriverState::starting;
  if (!set_up_) init_step_ = 0;
  (void)tick;
}

// Why keep the command and the firing in flight: their answers still come, and are taken (and
// dropped) by step() so that nothing stale is waiting when scanning resumes.
void PtuDriver::stop() {
  if (state_ == DriverState::starting || state_ == DriverState::scanning) state_ = DriverState::off;
  clear_scan();
}

void PtuDriver::fail(DriverFault f) {
  state_ = DriverState::failed;
  fault_ = f;
  pending_ = Command::none;
  echo_pending_ = false;
  if (f != DriverFault::lost && f != DriverFault::no_unit) set_up_ = false;  // start over next time
}

void PtuDriver::clear_scan() {
  const std::uint32_t sweeps = scan_.sweeps, readings = scan_.readings;
  scan_ = PanTiltScan{};
  scan_.sweeps = sweeps;
  scan_.readings = readings;
  scan_.fitted = stream_ != nullptr;
}

// Why always pump, even when off: a late reply left in the port would otherwise be taken as the
// answer to the first command after a restart.
bool PtuDriver::step(std::uint64_t tick, const SectorPose& pose) {
  if (stream_ == nullptr) return false;
  const bool active = state_ == DriverState::starting || state_ == DriverState::scanning;
  if (active && !stream_->connected()) {
    fail(DriverFault::lost);
    return false;
  }
  pump();
  if (state_ != DriverState::starting && state_ != DriverState::scanning) {
    if (echo_pending_) {
      hal::NodeRanges drop{};
      if (ring_.read(hal::kPanTiltChannel, drop) || tick - fire_tick_ > s_.echo_timeout_ticks) echo_pending_ = false;
    }
    if (pending_ != Command::none && tick - sent_tick_ > s_.reply_timeout_ticks) pending_ = Command::none;
    return false;
  }

  if (pending_ != Command::none && tick - sent_tick_ > s_.reply_timeout_ticks) {
    ++timeouts_;
    pending_ = Command::none;
    out_len_ = out_done_ = 0;
    lines_.clear();
    bad_reply(DriverFault::silent);
    if (state_ == DriverState::failed) return false;
  }
  bool changed = false;
  if (state_ == DriverState::scanning) {
    changed = collect_echo(tick);
    fire_if_due(tick, pose);
  }
  next_command(tick);
  flush();
  if (changed) scan_.tick = tick;
  return changed;
}

void PtuDriver::pump() {
  std::array<std::uint8_t, 64> buf{};
  for (int i = 0; i < kMaxReads; ++i) {
    const hal::IoResult r = stream_->read(buf);
    for (std::size_t k = 0; k < r.bytes; ++k) {
      if (!lines_.push(buf[k])) continue;
      const bool active = state_ == DriverState::starting || state_ == DriverState::scanning;
      if (active || pending_ != Command::none) handle_line(lines_.line(), lines_.bad());
    }
    if (r.closed) {
      if (state_ == DriverState::starting || state_ == DriverState::scanning) fail(DriverFault::lost);
      return;
    }
    if (r.bytes < buf.size()) return;
  }
}

void PtuDriver::bad_reply(DriverFault f) {
  const bool active = state_ == DriverState::starting || state_ == DriverState::scanning;
  if (active && ++failures_ >= s_.max_failures) fail(f);
}

// Why in order: the unit answers every command with exactly one line, in the order received.
void PtuDriver::handle_line(std::string_view line, bool bad) {
  const Command c = pending_;
  if (c == Command::none) {  // nothing asked (a late reply after a time-out, or noise)
    bad_reply(DriverFault::garbage);
    return;
  }
  pending_ = Command::none;
  const Reply r = bad ? Reply{} : parse_reply(line);
  if (state_ != DriverState::starting && state_ != DriverState::scanning) return;  // answered after a stop
  if (r.kind == ReplyKind::refused && c != Command::poll) {
    fail(DriverFault::refused);
    return;
  }
  if (r.kind != ReplyKind::ok) {
    bad_reply(DriverFault::garbage);
    return;
  }
  switch (c) {
    case Command::poll:
      if (!r.number || *r.number < s_.min_position - 100 || *r.number > s_.max_position + 100) {
        bad_reply(DriverFault::garbage);
        return;
      }
      on_position(*r.number, sent_tick_ + 1);
      break;
    case Command::echo_off:
    case Command::terse:
    case Command::immediate:
    case Command::acceleration:
    case Command::speed:
      ++init_step_;
      break;
    case Command::first_move:
      set_up_ = true;
      state_ = DriverState::scanning;
      break;
    default:
      break;
  }
  failures_ = 0;
}

// Why the tick after sending: the unit answers within a tick (≈ 10 bytes at 9600 bit/s), so
// that is when the position was true.
void PtuDriver::on_position(std::int32_t p, std::uint64_t measured_tick) {
  if (have_pos_ && measured_tick > pos_tick_) {
    const double dt = static_cast<double>(measured_tick - pos_tick_);
    const double avg = static_cast<double>(p - pos_) / dt;  // mean speed over the interval (its middle)
    const double amax = s_.acceleration * 1e-4;              // positions/tick² (10 ms ticks)
    accel_ = have_velocity_ ? std::clamp((avg - avg_velocity_) / dt, -amax, amax) : 0.0;
    velocity_ = avg + 0.5 * accel_ * dt;                     // at the end of the interval
    avg_velocity_ = avg;
    have_velocity_ = true;
  }
  pos_ = p;
  pos_tick_ = measured_tick;
  have_pos_ = true;
  if (std::abs(p - target_) <= s_.end_tolerance) reverse_due_ = true;
}

// Why step by step: the pan axis accelerates to its speed and no further, and brakes to a stop at
// an end — a plain v·t would overshoot both.
double PtuDriver::predict(std::uint64_t tick) const {
  const double vmax = s_.speed * 1e-2;  // positions/tick
  double p = pos_, v = velocity_;
  for (std::uint64_t t = pos_tick_; t < tick; ++t) {
    v = std::clamp(v + accel_, -vmax, vmax);
    p += v;
  }
  return std::clamp(p, static_cast<double>(s_.min_position), static_cast<double>(s_.max_position));
}

// The seed's start-up (ED, FT, I, PA6000, then move_ptu: ps1500, pp−1755), then PP every
// activation, and pp to the other end whenever an end is reached.
void PtuDriver::next_command(std::uint64_t tick) {
  if (pending_ != Command::none || out_done_ < out_len_) return;
  if (last_send_ != 0 && tick - last_send_ < s_.poll_period_ticks) return;
  if (state_ == DriverState::starting) {
    switch (init_step_) {
      case 0: return send(Command::echo_off, "ED", std::nullopt, tick);
      case 1: return send(Command::terse, "FT", std::nullopt, tick);
      case 2: return send(Command::immediate, "I", std::nullopt, tick);
      case 3: return send(Command::acceleration, "PA", s_.acceleration, tick);
      case 4: return send(Command::speed, "ps", s_.speed, tick);
      default: target_ = s_.min_position; return send(Command::first_move, "pp", target_, tick);
    }
  }
  if (reverse_due_) {
    reverse_due_ = false;
    target_ = target_ == s_.min_position ? s_.max_position : s_.min_position;
    ++scan_.sweeps;
    return send(Command::reverse, "pp", target_, tick);
  }
  send(Command::poll, "PP", std::nullopt, tick);
}

void PtuDriver::send(Command c, const char* text, std::optional<std::int32_t> n, std::uint64_t tick) {
  out_len_ = format_command(out_.data(), out_.size(), text, n);
  out_done_ = 0;
  pending_ = c;
  sent_tick_ = tick;
  last_send_ = tick;
}

void PtuDriver::flush() {
  if (out_done_ >= out_len_) return;
  const hal::IoResult w = stream_->write(std::span<const std::uint8_t>(
      reinterpret_cast<const std::uint8_t*>(out_.data()) + out_done_, out_len_ - out_done_));
  out_done_ += w.bytes;
  if (w.closed) fail(DriverFault::lost);
}

// Why predict: the position is a tick or more old when the activation fires (PP is answered at
// the next tick), and polls are 30 ms apart, 2.3° at 1500 positions/s; the prediction fires each
// sector at the tick whose angle is nearest its multiple of 5° (within 0.4° at that speed).
void PtuDriver::fire_if_due(std::uint64_t tick, const SectorPose& pose) {
  if (echo_pending_ || !have_pos_ || tick - pos_tick_ > s_.stale_ticks) return;
  const double now = predict(tick), next = predict(tick + 1);
  const double angle = position_to_angle(now);
  const int sector = sector_near(angle, s_.fire_tolerance_deg);
  if (sector < 0 || sector == last_sector_) return;
  const double target = kSectorDegrees * sector - 90.0;
  if (std::abs(position_to_angle(next) - target) < std::abs(angle - target)) return;  // the next tick is nearer
  if (!ring_.fire(hal::kPanTiltChannel, kBothSonars)) return;  // busy: the next tick may still catch it
  echo_pending_ = true;
  fire_sector_ = sector;
  fire_angle_ = angle;
  fire_tick_ = tick;
  fire_pose_ = pose;
  last_sector_ = sector;
  ++firings_;
}

bool PtuDriver::collect_echo(std::uint64_t tick) {
  if (!echo_pending_) return false;
  hal::NodeRanges r{};
  if (!ring_.read(hal::kPanTiltChannel, r)) {
    if (tick - fire_tick_ > s_.echo_timeout_ticks) {
      echo_pending_ = false;
      ++lost_echoes_;
    }
    return false;
  }
  echo_pending_ = false;
  // Seed read_pt(): temp[1] at (angle + 90)/5, temp[0] at the opposite sector.
  store(fire_sector_, r[1], fire_angle_ + 90.0);
  store(opposite_sector(fire_sector_), r[0], fire_angle_ + 270.0);
  spike_filter(scan_.raw, scan_.filtered, s_.filter);
  differences(scan_.filtered, scan_.differences);
  ++scan_.readings;
  return true;
}

void PtuDriver::store(int sector, std::uint16_t measured_mm, double direction_deg) {
  const auto i = static_cast<std::size_t>(sector);
  scan_.direction[i] = static_cast<std::int32_t>(std::lround(std::fmod(direction_deg + 360.0, 360.0) * 100.0));
  scan_.raw[i] = correct_range(measured_mm, s_.calibration);
  scan_.read_tick[i] = fire_tick_;
  scan_.pose[i] = fire_pose_;
}

}  // namespace robuter::ptu
