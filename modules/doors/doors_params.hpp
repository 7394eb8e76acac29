// SPDX-License-Identifier: GPL-3.0-or-later
// The door crossing's parameters ([doors]).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/param.hpp"

namespace robuter {

// The door crossing (seed doors.c, doors.h; docs/DOORS.md). The body and the pan-tilt's place on
// it (PAN_X/Y_POSITION, BOX_WIDTH): the robot model ([robot], [ptu] pivot_x_mm, box_width_mm).
struct DoorsConfig {
  std::uint32_t safety_mm = 35;              // clearance kept from obstacles (SAFETY_DIST), mm
  std::uint32_t max_dist_mm = 1500;          // a side all beyond this: through the door (MAX_DIST), mm
  std::uint32_t time_before_move_ticks = 500;  // blocked on both sides this long: can't cross (TIME_BEFORE_MOVE)
  std::uint32_t forward_cm_s = 2;            // speed going straight, cm/s
  std::uint32_t back_cm_s = 1;               // speed of the wheel that backs off in a turn, cm/s
  std::uint32_t entered_mm = 1500;           // both sides seen closer than this: inside the door, mm
  std::uint32_t beside_mm = 300;             // and those echoes this close to abreast of the pan axis, mm
  std::uint32_t exit_mm = 400;               // driven on after "through" so the rear clears the door, mm
  std::uint32_t max_age_ticks = 600;         // pan-tilt readings older than this are ignored, ticks
  std::uint32_t same_echo_mm = 20;           // neighbouring sectors this close in range see the same echo, mm
  std::uint32_t echo_spread_percent = 0;     // an echo is judged over this share of its bearing uncertainty, %
  std::uint32_t timeout_ticks = 30000;       // a crossing longer than this fails, ticks (0: no limit)
  std::uint32_t emergency_mask = 1;          // detections kept on while crossing (bumper 1)
};

// [doors]: each key, its unit, range and doc (the default is the field's initialiser).
std::span<const param::Param<DoorsConfig>> doors_params();

}  // namespace robuter
