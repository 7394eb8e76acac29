// SPDX-License-Identifier: GPL-3.0-or-later
// hal::SonarRing on CAN ultrasonic nodes (docs/CAN.md frame set): fire frames out, ranges and status back.
#pragma once

#include <array>
#include <cstdint>

#include "hal/api/sonar_ring.hpp"
#include "hal/linux/can/cia402.hpp"
#include "hal/linux/can/frame_transport.hpp"

namespace robuter::hal::can {

// Ring nodes 0..5 and the pan-tilt channel 7 are CAN nodes base + n. A node is usable while its
// heartbeat is fresh and it is operational; the backend starts (NMT) any that is not.
class CanSonarRing final : public SonarRing {
 public:
  static constexpr int kChannels = 8;  // node numbers 0..7 (6 unused)

  CanSonarRing(FrameTransport& bus, std::uint8_t node_base, std::uint32_t heartbeat_timeout_ms);
  void configure(std::uint32_t timeout_ms, std::uint32_t sound_speed_m_s) override;
  bool fire(int node, std::uint8_t mask, std::uint32_t timeout_ms = 0) override;
  bool read(int node, NodeRanges& out) override;

  void start(std::int64_t now_us);
  bool on_frame(const can_frame& f, std::int64_t now_us);
  // NMT start for nodes heard but not operational (at most once per 100 ms each).
  void poll(std::int64_t now_us);
  // Node n answers (fresh heartbeat, operational).
  bool alive(int node) const;
  std::uint8_t faulty(int node) const { return ch_[static_cast<std::size_t>(node)].faulty; }

 private:
  // One node as the host sees it.
  struct Channel {
    std::int64_t heard_us = -1;          // last heartbeat, µs (-1: never)
    cia402::NmtState nmt = cia402::NmtState::boot_up;  // state it reported
    std::int64_t start_sent_us = -1;     // last NMT start sent, µs
    bool pending = false;                // fired, ranges not yet back
    std::int64_t fired_us = 0;           // when, µs
    std::uint8_t mask = 0;               // transducers fired
    std::uint32_t timeout_ms = 0;        // that firing's echo time-out (sent in its fire frame), ms
    bool ready = false;                  // ranges back for the pending firing
    NodeRanges mm{};                     // those ranges, mm
    std::uint8_t faulty = 0;             // faulty transducers (status frame), bit i
  };
  // Node number for a CAN node id, or -1.
  int channel_of(std::uint8_t id) const;

  FrameTransport& bus_;
  std::uint8_t base_;
  std::int64_t timeout_us_;            // heartbeat time-out, µs
  std::uint32_t echo_timeout_ms_ = 33; // configured echo time-out, ms
  std::uint32_t sound_speed_ = 300;    // configured speed of sound, m/s
  std::int64_t now_us_ = 0;            // time of the latest poll or frame, µs
  std::array<Channel, kChannels> ch_{};
};

}  // namespace robuter::hal::can
