// SPDX-License-Identifier: GPL-3.0-or-later
// The emergency module's parameters ([emergency]): the table (compiled once, not in every includer of the configuration).
#include "modules/emergency/emergency_params.hpp"

namespace robuter {

namespace {
constexpr param::Param<EmergencyConfig> kEmergencyParams[] = {
    {"mask", &EmergencyConfig::mask, "bits", 0, 7, "",
     "enabled detections: bumper 1, ultrasonic 2, communication 4"},
    {"comm_limit_ticks", &EmergencyConfig::comm_limit_ticks, "ticks", 1, param::kU32, "",
     "link silence that trips, ticks (3 min)"},
    {"min_safety_mm", &EmergencyConfig::min_safety_mm, "mm", 0, 10'000, "",
     "smallest safety distance, mm"},
    {"safety_mm_per_cm_s", &EmergencyConfig::safety_mm_per_cm_s, "mm per cm/s", 0, 1000, "",
     "safety distance per cm/s of the faster wheel, mm"},
    {"motion_timeout_ms", &EmergencyConfig::motion_timeout_ms, "ms", 0, 3'600'000, "",
     "stop when no motion command for this long while moving; 0 = off"},
    {"auto_toggle", &EmergencyConfig::auto_toggle, "bool", 0, 0, "",
     "only the watch-dog sensors fire"},
    {"latch", &EmergencyConfig::latch, "bool", 0, 0, "",
     "a tripped emergency holds until re-enabled"},
    {"rule", &EmergencyConfig::rule, "word", 0, 0, "envelope|seed",
     "obstacle rule: \"envelope\" (swept body, docs/SAFETY.md §13) or \"seed\" (watch-dog sets)"},
    {"margin_mm", &EmergencyConfig::margin_mm, "mm", 0, 500, "",
     "envelope: clearance kept around the body, mm"},
    {"creep_cm_s", &EmergencyConfig::creep_cm_s, "cm/s", 0, 50, "",
     "envelope: fastest wheel where only the blind near field is unknown, cm/s"},
    {"free_age_ms", &EmergencyConfig::free_age_ms, "ms", 10, 600'000, "",
     "envelope: free space older than this is unknown again, ms"},
    {"single_echo_ms", &EmergencyConfig::single_echo_ms, "ms", 0, 600'000, "",
     "envelope: one echo's evidence that no later echo marks counts this long (0: for ever), ms"},
    {"narrow_arcs", &EmergencyConfig::narrow_arcs, "bool", 0, 0, "",
     "envelope: an echo meeting the a-priori map's walls marks only them and what no recent cone saw through (SAFETY.md §13)"},
    {"protective_clear_ms", &EmergencyConfig::protective_clear_ms, "ms", 0, 600'000, "",
     "envelope: an automatic mode resumes after this long clear, ms"},
    {"reaction_ms", &EmergencyConfig::reaction_ms, "ms", 0, 10'000, "",
     "envelope: from a decision to the next one reaching the drive, ms"},
};
}  // namespace

std::span<const param::Param<EmergencyConfig>> emergency_params() { return kEmergencyParams; }

}  // namespace robuter
