// SPDX-License-Identifier: GPL-3.0-or-later
// Identifiers of every command the protocol knows, one per command-table row.
#pragma once

#include <cstdint>

namespace robuter::protocol {

// Grouped by category; the table in command_table.cpp maps (category, type) to these.
enum class CommandId : std::uint8_t {
  none = 0,
  // B: information requests
  get_posture,             // BO
  get_ranges,              // BU
  get_posture_ranges,      // BV
  get_clock,               // BC
  get_us_timeout,          // BT
  get_pan_tilt_raw,        // BP
  get_pan_tilt_filtered,   // BF
  get_pan_tilt_differences,  // BD
  // A: commands
  move,                    // AM
  servo,                   // AS
  pass_through,            // AY
  set_odometry,            // AC
  go_to,                   // AW
  shutdown,                // AX
  pan_tilt_on,             // Ap
  pan_tilt_off,            // Ag
  gate_on,                 // AG
  gate_off,                // AT
  doors_on,                // Ad
  doors_off,               // Af
  // U: ultrasonic ring
  set_sensor_table,        // UT
  set_node_delay,          // UD
  get_node_delay,          // UN
  get_us_times,            // US (N or S)
  set_us_timeout,          // Ut
  set_auto_toggle,         // Uu
  // X: extensions of this project
  get_emergency,           // XE
  reenable,                // XR
  get_kernel_figures,      // XK
  get_version,             // XV
  set_stream,              // XS
  set_verbose_errors,      // XB
  set_checksums,           // XC
  set_terminator,          // XL
  set_goal,                // XG (grid planner)
  cancel_goal,             // XH
  get_planner_status,      // XP
  get_planner_map,         // XM
  get_modes,               // XD (pan-tilt, gate, doors, demo)
  set_demo,                // XT0 / XT1 (demonstration course)
  get_place,               // XN (the place the robot is in; docs/PLACES.md)
  get_place_info,          // XI <n> (one place of the place graph)
  go_to_place,             // XQ <n> (drive to a place over the place graph's route)
  get_localisation,        // XW (the pose on the map and its uncertainty; docs/LOCALISATION.md)
  set_map_pose,            // XA [x y theta] (the pose on the map, or a global search)
};

}  // namespace robuter::protocol
