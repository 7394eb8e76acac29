// SPDX-License-Identifier: GPL-3.0-or-later
// The passage finder's parameters ([gate]): the table (compiled once, not in every includer of the configuration).
#include "modules/gate/gate_params.hpp"

namespace robuter {

std::span<const param::Param<GateConfig>> gate_params() {
  using P = param::Param<GateConfig>;
  static constexpr P kRows[] = {
      P::integer("margin_mm", &GateConfig::margin_mm, "mm", 1, 10'000, "a jump of the differences above this marks a corner (MARGIN)"),
      P::integer("max_gap_sectors", &GateConfig::max_gap_sectors, "sectors", 1, 36, "a passage spans fewer far sectors than this (in_door < 8)"),
      P::integer("min_mm", &GateConfig::min_mm, "mm", 0, 10'000, "a corner this close ends the approach (MIN)"),
      P::integer("max_mm", &GateConfig::max_mm, "mm", 100, 20'000, "a corner reading at or beyond this is no corner (MAX)"),
      P::integer("speed_cm_s", &GateConfig::speed_cm_s, "cm/s", 1, 100, "driving speed (Va), cm/s"),
      P::integer("turn_cm_s", &GateConfig::turn_cm_s, "cm/s", 1, 100, "turning speed of each wheel (Va/2), cm/s"),
      P::integer("timeout_ticks", &GateConfig::timeout_ticks, "ticks", 1, 1'000'000, "no passage locked for this long: give up (TIMEOUT), ticks"),
      P::integer("stage_mm", &GateConfig::stage_mm, "mm", 50, 5000, "aligned with the front face this far from the passage, mm"),
      P::integer("lateral_tolerance_mm", &GateConfig::lateral_tolerance_mm, "mm", 1, 1000, "aligned when the axle is this close to the centre line, mm"),
      P::integer("heading_tolerance_centideg", &GateConfig::heading_tolerance_centideg, "0.01°", 10, 3000, "and the heading this close to the passage's normal, 0.01°"),
      P::integer("max_manoeuvres", &GateConfig::max_manoeuvres, "", 1, 100, "manoeuvres allowed before giving up"),
      P::integer("stall_ticks", &GateConfig::stall_ticks, "ticks", 50, 1'000'000, "a manoeuvre the robot has not moved in for this long backs off, ticks"),
      P::integer("back_off_mm", &GateConfig::back_off_mm, "mm", 0, 2000, "how far it backs off before scanning again, mm"),
      P::flag("hand_over", &GateConfig::hand_over, "start the door crossing when aligned (the seed's door = ON); off: it lowers the sonar without a 2nd command (SAFETY.md §1)"),
  };
  return kRows;
}

}  // namespace robuter
