// SPDX-License-Identifier: GPL-3.0-or-later
// The passage finder's parameters ([gate]).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/param.hpp"

namespace robuter {

// The passage finder (seed gate.c, gate.h; docs/DOORS.md).
struct GateConfig {
  std::uint32_t margin_mm = 300;             // a jump of the differences above this marks a corner (MARGIN)
  std::uint32_t max_gap_sectors = 8;         // a passage spans fewer far sectors than this (in_door < 8)
  std::uint32_t min_mm = 700;                // a corner this close ends the approach (MIN)
  std::uint32_t max_mm = 2300;               // a corner reading at or beyond this is no corner (MAX)
  std::uint32_t speed_cm_s = 5;              // driving speed (Va), cm/s
  std::uint32_t turn_cm_s = 2;               // turning speed of each wheel (Va/2), cm/s
  std::uint32_t timeout_ticks = 1000;        // no passage locked for this long: give up (TIMEOUT), ticks
  std::uint32_t stage_mm = 300;              // aligned with the front face this far from the passage, mm
  std::uint32_t lateral_tolerance_mm = 30;   // aligned when the axle is this close to the centre line, mm
  std::uint32_t heading_tolerance_centideg = 200;  // and the heading this close to the passage's normal, 0.01°
  std::uint32_t max_manoeuvres = 6;          // manoeuvres allowed before giving up
  std::uint32_t stall_ticks = 500;           // a manoeuvre the robot has not moved in for this long backs off, ticks
  std::uint32_t back_off_mm = 250;           // how far it backs off before scanning again, mm
  bool hand_over = false;                    // start the door crossing when aligned (the seed's door = ON); off: it lowers the sonar without a 2nd command (SAFETY.md §1)
};

// [gate]: each key, its unit, range and doc (the default is the field's initialiser).
std::span<const param::Param<GateConfig>> gate_params();

}  // namespace robuter
