// SPDX-License-Identifier: GPL-3.0-or-later
// What robuter-can-nodes prints about a simulated drive: state changes, motion, heartbeat events.
#pragma once

#include <cstdint>
#include <cstdio>

#include "hal/linux/can/sim_nodes.hpp"

namespace robuter::tools {

// Compares a drive with what was last printed and prints one line per change, stamped with the
// tool's time in ms: CiA 402 state, moving / standing still (with the time since the watched
// heartbeat's last frame), heartbeat events of the consumer.
class NodeReport {
 public:
  NodeReport(const hal::can::SimDriveNode& drive, std::uint8_t node) : drive_(drive), node_(node) {}
  void update(std::int64_t now_us, std::FILE* out);

 private:
  const hal::can::SimDriveNode& drive_;
  std::uint8_t node_;                                        // its node id
  hal::can::cia402::State state_ = hal::can::cia402::State::not_ready_to_switch_on;  // last printed
  bool moving_ = false;                                      // last printed
  std::uint32_t events_ = 0;                                 // heartbeat events printed, count
  bool consumer_printed_ = false;                            // the consumer set-up was printed
};

}  // namespace robuter::tools
