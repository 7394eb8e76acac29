// SPDX-License-Identifier: GPL-3.0-or-later
// Change lines of one simulated drive.
#include "tools/robuter-can-nodes/node_report.hpp"

#include <cmath>

namespace robuter::tools {


void NodeReport::update(std::int64_t now_us, std::FILE* out) {
  const double t_ms = static_cast<double>(now_us) / 1000.0;
  const std::int64_t last = drive_.last_consumed_us();
  const double since_ms = last < 0 ? -1.0 : static_cast<double>(now_us - last) / 1000.0;
  if (!consumer_printed_ && drive_.consumer_ms() > 0 && drive_.abort_option() != 1) {
    consumer_printed_ = true;
    std::fprintf(out, "t=%.1f node %u: watches node %u's heartbeat, %u ms, reaction 0x6007=%d\n", t_ms, node_,
                 drive_.consumer_node(), drive_.consumer_ms(), drive_.abort_option());
  }
  if (drive_.heartbeat_events() != events_) {
    events_ = drive_.heartbeat_events();
    std::fprintf(out, "t=%.1f node %u: heartbeat of node %u lost (%.1f ms since the last, consumer time %u ms): "
                      "reaction 0x6007=%d\n",
                 t_ms, node_, drive_.consumer_node(), since_ms, drive_.consumer_ms(), drive_.abort_option());
  }
  if (drive_.state() != state_) {
    state_ = drive_.state();
    const std::string_view state_word = word(state_);
    std::fprintf(out, "t=%.1f node %u: state %.*s (%.1f ms since node %u's last heartbeat)\n", t_ms, node_,
                 static_cast<int>(state_word.size()), state_word.data(), since_ms, drive_.consumer_node());
  }
  const bool moving = std::fabs(drive_.velocity()) >= 0.5;
  if (moving != moving_) {
    moving_ = moving;
    if (moving)
      std::fprintf(out, "t=%.1f node %u: moving, target %d increments/s\n", t_ms, node_, drive_.target_velocity());
    else
      std::fprintf(out, "t=%.1f node %u: standing still, %.1f ms after node %u's last heartbeat\n", t_ms, node_,
                   since_ms, drive_.consumer_node());
  }
  std::fflush(out);
}

}  // namespace robuter::tools
