// SPDX-License-Identifier: GPL-3.0-or-later
// Declarations of the command handlers the command table points to.
#pragma once

#include "protocol/codec/command.hpp"
#include "protocol/codec/port_types.hpp"
#include "protocol/codec/reply_writer.hpp"
#include "protocol/codec/robot_port.hpp"

namespace robuter::protocol {

// Turns a port's answer into `ack` or the matching `error`.
void reply_result(PortResult result, ReplyWriter& out) noexcept;
// True when the port refused (anything but ok): the reply is then the matching `error`. A report's
// handler asks with it and stops there: `if (refused(port.planner_status(r), out)) return;`.
bool refused(PortResult result, ReplyWriter& out) noexcept;
// The error code a port result stands for (ok → none).
ErrorCode error_for(PortResult result) noexcept;

// B: information requests (handlers_info.cpp)
void handle_get_posture(const Command&, RobotPort&, ReplyWriter&) noexcept;          // BO
void handle_get_ranges(const Command&, RobotPort&, ReplyWriter&) noexcept;           // BU
void handle_get_posture_ranges(const Command&, RobotPort&, ReplyWriter&) noexcept;   // BV
void handle_get_clock(const Command&, RobotPort&, ReplyWriter&) noexcept;            // BC
void handle_get_us_timeout(const Command&, RobotPort&, ReplyWriter&) noexcept;       // BT
void handle_get_pan_tilt_raw(const Command&, RobotPort&, ReplyWriter&) noexcept;     // BP
void handle_get_pan_tilt_filtered(const Command&, RobotPort&, ReplyWriter&) noexcept;  // BF
void handle_get_pan_tilt_differences(const Command&, RobotPort&, ReplyWriter&) noexcept;  // BD

// A: commands (handlers_action.cpp)
void handle_move(const Command&, RobotPort&, ReplyWriter&) noexcept;          // AM
void handle_servo(const Command&, RobotPort&, ReplyWriter&) noexcept;         // AS
void handle_pass_through(const Command&, RobotPort&, ReplyWriter&) noexcept;  // AY
void handle_set_odometry(const Command&, RobotPort&, ReplyWriter&) noexcept;  // AC
void handle_go_to(const Command&, RobotPort&, ReplyWriter&) noexcept;         // AW
void handle_shutdown(const Command&, RobotPort&, ReplyWriter&) noexcept;      // AX

// Ap/Ag, AG/AT, Ad/Af: one template for every on/off switch of a module.
template <PortResult (RobotPort::*Set)(bool) noexcept, bool On>
void handle_switch(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  reply_result((port.*Set)(On), out);
}

// U: ultrasonic ring (handlers_ultrasonic.cpp)
void handle_set_sensor_table(const Command&, RobotPort&, ReplyWriter&) noexcept;  // UT
void handle_set_node_delay(const Command&, RobotPort&, ReplyWriter&) noexcept;    // UD
void handle_get_node_delay(const Command&, RobotPort&, ReplyWriter&) noexcept;    // UN
void handle_get_us_times(const Command&, RobotPort&, ReplyWriter&) noexcept;      // USN/USS
void handle_set_us_timeout(const Command&, RobotPort&, ReplyWriter&) noexcept;    // Ut
void handle_set_auto_toggle(const Command&, RobotPort&, ReplyWriter&) noexcept;   // Uu

// X: extensions (handlers_extension.cpp)
void handle_get_emergency(const Command&, RobotPort&, ReplyWriter&) noexcept;       // XE
void handle_reenable(const Command&, RobotPort&, ReplyWriter&) noexcept;            // XR
void handle_get_kernel_figures(const Command&, RobotPort&, ReplyWriter&) noexcept;  // XK
void handle_get_version(const Command&, RobotPort&, ReplyWriter&) noexcept;         // XV
void handle_set_stream(const Command&, RobotPort&, ReplyWriter&) noexcept;          // XS
void handle_set_verbose_errors(const Command&, RobotPort&, ReplyWriter&) noexcept;  // XB
void handle_set_checksums(const Command&, RobotPort&, ReplyWriter&) noexcept;       // XC
void handle_set_terminator(const Command&, RobotPort&, ReplyWriter&) noexcept;      // XL

// X: the grid planner (handlers_planner.cpp)
void handle_set_goal(const Command&, RobotPort&, ReplyWriter&) noexcept;            // XG
void handle_cancel_goal(const Command&, RobotPort&, ReplyWriter&) noexcept;         // XH
void handle_get_planner_status(const Command&, RobotPort&, ReplyWriter&) noexcept;  // XP
void handle_get_planner_map(const Command&, RobotPort&, ReplyWriter&) noexcept;     // XM
void handle_get_place(const Command&, RobotPort&, ReplyWriter&) noexcept;           // XN
void handle_get_place_info(const Command&, RobotPort&, ReplyWriter&) noexcept;      // XI
void handle_go_to_place(const Command&, RobotPort&, ReplyWriter&) noexcept;         // XQ

// X: localisation (handlers_localise.cpp)
void handle_get_localisation(const Command&, RobotPort&, ReplyWriter&) noexcept;    // XW
void handle_set_map_pose(const Command&, RobotPort&, ReplyWriter&) noexcept;        // XA

// X: pan-tilt, passage finder, door crossing and demonstration (handlers_modes.cpp)
void handle_get_modes(const Command&, RobotPort&, ReplyWriter&) noexcept;           // XD
void handle_set_demo(const Command&, RobotPort&, ReplyWriter&) noexcept;            // XT

}  // namespace robuter::protocol
