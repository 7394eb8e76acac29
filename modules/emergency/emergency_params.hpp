// SPDX-License-Identifier: GPL-3.0-or-later
// The emergency module's parameters ([emergency]).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/param.hpp"

namespace robuter {

// Emergency watchdog (emerg.c).
struct EmergencyConfig {
  std::uint32_t mask = 7;                    // enabled detections: bumper 1, ultrasonic 2, communication 4
  std::uint32_t comm_limit_ticks = 18'000;   // link silence that trips, ticks (3 min)
  std::uint32_t min_safety_mm = 220;         // smallest safety distance, mm
  std::uint32_t safety_mm_per_cm_s = 10;     // safety distance per cm/s of the faster wheel, mm
  std::uint32_t motion_timeout_ms = 0;       // stop when no motion command for this long while moving; 0 = off
  bool auto_toggle = false;                  // only the watch-dog sensors fire
  bool latch = true;                         // a tripped emergency holds until re-enabled
  std::string rule = "envelope";             // obstacle rule: "envelope" (swept body, docs/SAFETY.md §13) or "seed" (watch-dog sets)
  std::uint32_t margin_mm = 30;              // envelope: clearance kept around the body, mm
  std::uint32_t creep_cm_s = 20;             // envelope: fastest wheel where only the blind near field is unknown, cm/s
  std::uint32_t free_age_ms = 3000;          // envelope: free space older than this is unknown again, ms
  std::uint32_t single_echo_ms = 3000;       // envelope: one echo's evidence that no later echo marks counts this long (0: for ever), ms
  bool narrow_arcs = true;                   // envelope: an echo meeting the a-priori map's walls marks only them and what no recent cone saw through (SAFETY.md §13)
  std::uint32_t protective_clear_ms = 1000;  // envelope: an automatic mode resumes after this long clear, ms
  std::uint32_t reaction_ms = 110;           // envelope: from a decision to the next one reaching the drive, ms
};

// [emergency]: each key, its unit, range and doc (the default is the field's initialiser).
std::span<const param::Param<EmergencyConfig>> emergency_params();

}  // namespace robuter
