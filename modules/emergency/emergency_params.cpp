// SPDX-License-Identifier: GPL-3.0-or-later
// The emergency module's parameters ([emergency]): the table (compiled once, not in every includer of the configuration).
#include "modules/emergency/emergency_params.hpp"

namespace robuter {

std::span<const param::Param<EmergencyConfig>> emergency_params() {
  using P = param::Param<EmergencyConfig>;
  static constexpr P kRows[] = {
      P::integer("mask", &EmergencyConfig::mask, "bits", 0, 7, "enabled detections: bumper 1, ultrasonic 2, communication 4"),
      P::integer("comm_limit_ticks", &EmergencyConfig::comm_limit_ticks, "ticks", 1, param::kU32, "link silence that trips, ticks (3 min)"),
      P::integer("min_safety_mm", &EmergencyConfig::min_safety_mm, "mm", 0, 10'000, "smallest safety distance, mm"),
      P::integer("safety_mm_per_cm_s", &EmergencyConfig::safety_mm_per_cm_s, "mm per cm/s", 0, 1000, "safety distance per cm/s of the faster wheel, mm"),
      P::integer("motion_timeout_ms", &EmergencyConfig::motion_timeout_ms, "ms", 0, 3'600'000, "stop when no motion command for this long while moving; 0 = off"),
      P::flag("auto_toggle", &EmergencyConfig::auto_toggle, "only the watch-dog sensors fire"),
      P::flag("latch", &EmergencyConfig::latch, "a tripped emergency holds until re-enabled"),
      P::word("rule", &EmergencyConfig::rule, "envelope|seed", "obstacle rule: \"envelope\" (swept body, docs/SAFETY.md §13) or \"seed\" (watch-dog sets)"),
      P::integer("margin_mm", &EmergencyConfig::margin_mm, "mm", 0, 500, "envelope: clearance kept around the body, mm"),
      P::integer("creep_cm_s", &EmergencyConfig::creep_cm_s, "cm/s", 0, 50, "envelope: fastest wheel where only the blind near field is unknown, cm/s"),
      P::integer("free_age_ms", &EmergencyConfig::free_age_ms, "ms", 10, 600'000, "envelope: free space older than this is unknown again, ms"),
      P::integer("single_echo_ms", &EmergencyConfig::single_echo_ms, "ms", 0, 600'000, "envelope: one echo's evidence that no later echo marks counts this long (0: for ever), ms"),
      P::flag("narrow_arcs", &EmergencyConfig::narrow_arcs, "envelope: an echo meeting the a-priori map's walls marks only them and what no recent cone saw through (SAFETY.md §13)"),
      P::integer("protective_clear_ms", &EmergencyConfig::protective_clear_ms, "ms", 0, 600'000, "envelope: an automatic mode resumes after this long clear, ms"),
      P::integer("reaction_ms", &EmergencyConfig::reaction_ms, "ms", 0, 10'000, "envelope: from a decision to the next one reaching the drive, ms"),
  };
  return kRows;
}

}  // namespace robuter
