// SPDX-License-Identifier: GPL-3.0-or-later
// The grid planner's parameters ([planner]): the table (compiled once, not in every includer of the configuration).
#include "modules/planner/planner_params.hpp"

namespace robuter {

std::span<const param::Param<PlannerModuleConfig>> planner_params() {
  using P = param::Param<PlannerModuleConfig>;
  static constexpr P kRows[] = {
      P::integer("map_origin_x_mm", &PlannerModuleConfig::map_origin_x_mm, "mm", -kPlannerFarMm, kPlannerFarMm, "lower-left corner of the map, odometry frame, mm"),
      P::integer("map_origin_y_mm", &PlannerModuleConfig::map_origin_y_mm, "mm", -kPlannerFarMm, kPlannerFarMm, "lower-left corner of the map, odometry frame, y, mm"),
      P::integer("map_width_mm", &PlannerModuleConfig::map_width_mm, "mm", 500, kPlannerFarMm, "map extent along x, mm"),
      P::integer("map_height_mm", &PlannerModuleConfig::map_height_mm, "mm", 500, kPlannerFarMm, "map extent along y, mm"),
      P::integer("cell_mm", &PlannerModuleConfig::cell_mm, "mm", 10, 500, "cell side, mm (seed 000: 5 cm)"),
      P::word("footprint", &PlannerModuleConfig::footprint, "rectangle|disc", "\"rectangle\" (the body, with heading) or \"disc\""),
      P::integer("disc_radius_mm", &PlannerModuleConfig::disc_radius_mm, "mm", 50, 5000, "disc footprint radius, mm (axle to a front corner)"),
      P::integer("margin_mm", &PlannerModuleConfig::margin_mm, "mm", 0, 1000, "clearance added all round the body to translate, mm"),
      P::integer("turn_clearance_mm", &PlannerModuleConfig::turn_clearance_mm, "mm", 0, 1000, "more clearance needed to turn in place, mm"),
      P::integer("heading_slices", &PlannerModuleConfig::heading_slices, "", 4, 64, "heading slices over a half turn (rectangle)"),
      P::integer("hit_threshold", &PlannerModuleConfig::hit_threshold, "hits", 1, 254, "net sonar hits that make a cell an obstacle"),
      P::integer("initial_count", &PlannerModuleConfig::initial_count, "hits", 0, 253, "count a never-seen cell starts from when a beam first touches it (seed 003: 5)"),
      P::text("map_file", &PlannerModuleConfig::map_file, "path", "a-priori map (\"robuter-map 1\", odometry frame), resolved against the configuration's folder; empty = none"),
      P::integer("scan_passes", &PlannerModuleConfig::scan_passes, "", 1, 20, "full ring passes waited for at each stop"),
      P::integer("beam_range_mm", &PlannerModuleConfig::beam_range_mm, "mm", 200, 10'000, "readings marked up to this range, mm"),
      P::integer("beam_half_angle_centideg", &PlannerModuleConfig::beam_half_angle_centideg, "0.01°", 0, 4500, "ring sonar cone half-angle, 0.01° (0: axis only)"),
      P::integer("follow_range_mm", &PlannerModuleConfig::follow_range_mm, "mm", 100, 10'000, "the path is followed this far before a new scan, mm"),
      P::integer("goal_tolerance_mm", &PlannerModuleConfig::goal_tolerance_mm, "mm", 10, 5000, "arrived within this distance of the goal, mm"),
      P::integer("drive_speed_cm_s", &PlannerModuleConfig::drive_speed_cm_s, "cm/s", 1, 100, "fastest wheel while driving, cm/s"),
      P::integer("turn_speed_cm_s", &PlannerModuleConfig::turn_speed_cm_s, "cm/s", 1, 100, "fastest wheel while turning in place, cm/s"),
  };
  return kRows;
}

}  // namespace robuter
