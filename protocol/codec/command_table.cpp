// SPDX-License-Identifier: GPL-3.0-or-later
// The protocol's command table: every seed message and every extension, one row each.
#include "protocol/codec/command_table.hpp"

#include <array>

#include "protocol/codec/handlers.hpp"

namespace robuter::protocol {
namespace {

// Parameter ranges, in the units of docs/PROTOCOL.md. The port may refuse narrower ranges.
constexpr IntRange kAny{};                   // any 32-bit value (x, y in 0.1 mm)
constexpr IntRange kTheta{-17999, 18000};     // 0.01 degree, (-180, 180]
constexpr IntRange kPlaceNumber{1, 9999};   // a place's number, 1-based in the file's order
constexpr IntRange kFlag{0, 1};              // off / on
constexpr IntRange kSpeed{-1000, 1000};      // cm/s: far beyond any Robuter, a sanity bound
constexpr IntRange kNodeDelay{0, 1000};      // ticks
constexpr IntRange kUsTimeout{1, 1000};      // ms
constexpr IntRange kStreamPeriod{0, static_cast<std::int32_t>(kMaxStreamPeriod)};  // ticks

using C = CommandId;

constexpr std::array kCommands = {
    // B — information requests
    CommandRow{'B', 'O', C::get_posture, no_params(), handle_get_posture, "posture"},
    CommandRow{'B', 'U', C::get_ranges, no_params(), handle_get_ranges, "ultrasonic ranges"},
    CommandRow{'B', 'V', C::get_posture_ranges, no_params(), handle_get_posture_ranges,
               "posture and ranges"},
    CommandRow{'B', 'C', C::get_clock, no_params(), handle_get_clock, "clock"},
    CommandRow{'B', 'T', C::get_us_timeout, no_params(), handle_get_us_timeout,
               "ultrasonic time-out"},
    CommandRow{'B', 'P', C::get_pan_tilt_raw, no_params(), handle_get_pan_tilt_raw,
               "pan-tilt ranges"},
    CommandRow{'B', 'F', C::get_pan_tilt_filtered, no_params(), handle_get_pan_tilt_filtered,
               "pan-tilt filtered ranges"},
    CommandRow{'B', 'D', C::get_pan_tilt_differences, no_params(),
               handle_get_pan_tilt_differences, "pan-tilt differences"},
    // A — commands
    CommandRow{'A', 'M', C::move, integers(kSpeed, kSpeed), handle_move, "wheel speeds"},
    CommandRow{'A', 'S', C::servo, one_of("NF"), handle_servo, "servo on/off"},
    CommandRow{'A', 'Y', C::pass_through, rest_of_line(), handle_pass_through, "pass-through"},
    CommandRow{'A', 'C', C::set_odometry, integers(kAny, kAny, kTheta), handle_set_odometry,
               "set odometry"},
    CommandRow{'A', 'W', C::go_to, integers(kAny, kAny, kTheta), handle_go_to, "go to posture"},
    CommandRow{'A', 'X', C::shutdown, no_params(), handle_shutdown, "shut down"},
    CommandRow{'A', 'p', C::pan_tilt_on, no_params(),
               handle_switch<&RobotPort::set_pan_tilt, true>, "pan-tilt on"},
    CommandRow{'A', 'g', C::pan_tilt_off, no_params(),
               handle_switch<&RobotPort::set_pan_tilt, false>, "pan-tilt off"},
    CommandRow{'A', 'G', C::gate_on, no_params(),
               handle_switch<&RobotPort::set_gate_finder, true>, "passage finder on"},
    CommandRow{'A', 'T', C::gate_off, no_params(),
               handle_switch<&RobotPort::set_gate_finder, false>, "passage finder off"},
    CommandRow{'A', 'd', C::doors_on, no_params(),
               handle_switch<&RobotPort::set_door_crossing, true>, "door crossing on"},
    CommandRow{'A', 'f', C::doors_off, no_params(),
               handle_switch<&RobotPort::set_door_crossing, false>, "door crossing off"},
    // U — ultrasonic ring
    CommandRow{'U', 'T', C::set_sensor_table, sensor_table(), handle_set_sensor_table,
               "active sensors"},
    CommandRow{'U', 'D', C::set_node_delay, integers(kNodeDelay), handle_set_node_delay,
               "set node delay"},
    CommandRow{'U', 'N', C::get_node_delay, no_params(), handle_get_node_delay, "node delay"},
    CommandRow{'U', 'S', C::get_us_times, one_of("NS"), handle_get_us_times,
               "mean node/scan time"},
    CommandRow{'U', 't', C::set_us_timeout, integers(kUsTimeout), handle_set_us_timeout,
               "set ultrasonic time-out"},
    CommandRow{'U', 'u', C::set_auto_toggle, one_of("01"), handle_set_auto_toggle,
               "auto-toggle off/on"},
    // X — extensions of this project (docs/PROTOCOL.md, "Extensions")
    CommandRow{'X', 'E', C::get_emergency, no_params(), handle_get_emergency, "emergency state"},
    CommandRow{'X', 'R', C::reenable, no_params(), handle_reenable, "re-enable after emergency"},
    CommandRow{'X', 'K', C::get_kernel_figures, no_params(), handle_get_kernel_figures,
               "kernel statistics"},
    CommandRow{'X', 'V', C::get_version, no_params(), handle_get_version,
               "version and capabilities"},
    CommandRow{'X', 'S', C::set_stream, integers(kStreamPeriod), handle_set_stream,
               "status streaming period"},
    CommandRow{'X', 'B', C::set_verbose_errors, one_of("01"), handle_set_verbose_errors,
               "verbose errors off/on"},
    CommandRow{'X', 'C', C::set_checksums, one_of("01"), handle_set_checksums,
               "line checksums off/on"},
    CommandRow{'X', 'L', C::set_terminator, one_of("012"), handle_set_terminator,
               "reply terminator CR/LF/CRLF"},
    CommandRow{'X', 'G', C::set_goal, integers_from(2, kAny, kAny, kTheta), handle_set_goal,
               "planner goal x y [theta]"},
    CommandRow{'X', 'H', C::cancel_goal, no_params(), handle_cancel_goal, "planner halt (cancel goal)"},
    CommandRow{'X', 'P', C::get_planner_status, no_params(), handle_get_planner_status,
               "planner status"},
    CommandRow{'X', 'M', C::get_planner_map, no_params(), handle_get_planner_map,
               "planner map around the robot"},
    CommandRow{'X', 'D', C::get_modes, no_params(), handle_get_modes, "pan-tilt, gate, door-crossing and demonstration states"},
    CommandRow{'X', 'T', C::set_demo, one_of("01"), handle_set_demo, "demonstration course stop/start"},
    CommandRow{'X', 'N', C::get_place, no_params(), handle_get_place, "the place the robot is in (place graph)"},
    CommandRow{'X', 'I', C::get_place_info, integers(kPlaceNumber), handle_get_place_info,
               "place n: name, centre, neighbours"},
    CommandRow{'X', 'Q', C::go_to_place, integers_from(1, kPlaceNumber, kFlag), handle_go_to_place,
               "go to place n (route over the place graph) [1: exploring, a full-turn scan at each place]"},
    CommandRow{'X', 'W', C::get_localisation, no_params(), handle_get_localisation,
               "where the robot is on its map: pose and uncertainty (localisation)"},
    CommandRow{'X', 'A', C::set_map_pose, integers_or_none(kAny, kAny, kTheta), handle_set_map_pose,
               "the robot's pose on its map [x y theta]; none: a global search"},
};

}  // namespace

// The table as a span, for documentation tools and tests.
std::span<const CommandRow> command_table() noexcept { return kCommands; }

// Linear search: 39 rows of two bytes each is faster than any index worth keeping.
const CommandRow* find_command(char category, char type) noexcept {
  for (const CommandRow& row : kCommands) {
    if (row.category == category && row.type == type) return &row;
  }
  return nullptr;
}

}  // namespace robuter::protocol
