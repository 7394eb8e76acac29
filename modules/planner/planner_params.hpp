// SPDX-License-Identifier: GPL-3.0-or-later
// The grid planner's parameters ([planner]).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/param.hpp"
#include "robot/robot_model.hpp"

namespace robuter {

// The grid planner (modules/planner): its map, robot model, sonar use and motion.
struct PlannerModuleConfig {
  std::int32_t map_origin_x_mm = -8000;  // lower-left corner of the map, odometry frame, mm
  std::int32_t map_origin_y_mm = -8000;  // mm
  std::uint32_t map_width_mm = 16000;    // map extent along x, mm
  std::uint32_t map_height_mm = 16000;   // map extent along y, mm
  std::uint32_t cell_mm = 50;            // cell side, mm (seed 000: 5 cm)
  std::string footprint = "rectangle";   // "rectangle" (the body, with heading) or "disc"
  std::uint32_t disc_radius_mm = 780;    // disc footprint radius, mm (axle to a front corner)
  std::uint32_t margin_mm = 0;           // clearance added all round the body to translate, mm
  std::uint32_t turn_clearance_mm = 250; // more clearance needed to turn in place, mm
  std::uint32_t heading_slices = 16;     // heading slices over a half turn (rectangle)
  std::uint32_t hit_threshold = 2;       // net sonar hits that make a cell an obstacle
  std::uint32_t initial_count = 0;       // count a never-seen cell starts from when a beam first touches it (seed 003: 5)
  std::string map_file;                  // a-priori map ("robuter-map 1", odometry frame), resolved against the configuration's folder; empty = none
  int map_file_line = 0;                 // line of planner.map_file in the configuration (0: not written)
  std::array<int, 5> geometry_lines{};   // lines of map_origin_x_mm, map_origin_y_mm, map_width_mm, map_height_mm, cell_mm in the configuration (0: not written)
  std::uint32_t scan_passes = 2;         // full ring passes waited for at each stop
  std::uint32_t beam_range_mm = 2500;    // readings marked up to this range, mm
  std::uint32_t beam_half_angle_centideg = static_cast<std::uint32_t>(robot::centideg(robot::kRobuter.ring.half_angle));  // ring sonar cone half-angle, 0.01° (0: axis only)
  std::uint32_t follow_range_mm = 1500;  // the path is followed this far before a new scan, mm
  std::uint32_t goal_tolerance_mm = 100; // arrived within this distance of the goal, mm
  std::uint32_t drive_speed_cm_s = 20;   // fastest wheel while driving, cm/s
  std::uint32_t turn_speed_cm_s = 10;    // fastest wheel while turning in place, cm/s
};

// The farthest a map's corner or extent may reach, mm: 1 km, beyond any room.
inline constexpr long long kPlannerFarMm = 1'000'000;

// [planner]: each key, its unit, range and doc (the default is the field's initialiser).
std::span<const param::Param<PlannerModuleConfig>> planner_params();

// Why: the largest map (cells) the planner may be sized for, about 200 MB: checked for the
// configured map and for an a-priori map file alike.
long long planner_cell_limit(const PlannerModuleConfig& p);

}  // namespace robuter
