// SPDX-License-Identifier: GPL-3.0-or-later
// Handlers of the U messages: sensor table, node delay, timing figures, time-out, auto-toggle.
#include "protocol/codec/handlers.hpp"

namespace robuter::protocol {

// UT<24 × 0/1>: the port knows whether auto-toggle lets the table apply.
void handle_set_sensor_table(const Command& cmd, RobotPort& port, ReplyWriter& out) noexcept {
  reply_result(port.set_sensor_table(cmd.table), out);
}

// UD<ticks>.
void handle_set_node_delay(const Command& cmd, RobotPort& port, ReplyWriter& out) noexcept {
  reply_result(port.set_node_delay(cmd.ints[0]), out);
}

// UN → `N <ticks>`.
void handle_get_node_delay(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  out.open("N");
  out.field(port.node_delay());
}

// USN → `S <ticks>` for one node, USS → `S <ticks>` for a full scan.
void handle_get_us_times(const Command& cmd, RobotPort& port, ReplyWriter& out) noexcept {
  out.open("S");
  out.field(cmd.choice == 'N' ? port.mean_node_time() : port.mean_scan_time());
}

// Ut<ms>.
void handle_set_us_timeout(const Command& cmd, RobotPort& port, ReplyWriter& out) noexcept {
  reply_result(port.set_us_timeout(cmd.ints[0]), out);
}

// Uu0 / Uu1.
void handle_set_auto_toggle(const Command& cmd, RobotPort& port, ReplyWriter& out) noexcept {
  reply_result(port.set_auto_toggle(cmd.choice == '1'), out);
}

}  // namespace robuter::protocol
