// SPDX-License-Identifier: GPL-3.0-or-later
// The planner module's settings in the units it works in (m, rad), made from the configuration.
#pragma once

#include <cstdint>

#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/planner/lib/planner.hpp"
#include "modules/planner/planner_params.hpp"
#include "modules/places/places_params.hpp"
#include "modules/ptu/ptu_params.hpp"
#include "robot/robot_model.hpp"

namespace robuter::planner {

// Everything the module needs, converted once at construction.
struct PlannerSettings {
  plan::MapGeometry map;               // cells, m per cell, origin (m, odometry frame)
  std::uint8_t hit_threshold = 2;      // net hits for an obstacle cell
  std::uint8_t initial_count = 0;      // count of a never-seen cell at its first beam (seed 003: 5)
  plan::PlannerConfig planner;         // footprint, slices, clearances (m)
  robot::RobotModel robot = robot::kRobuter;  // body, ring mounts, pan-tilt mount (m, rad)
  std::uint32_t scan_passes = 2;       // full ring passes per stop
  double beam_range = 2.5;             // m, readings marked up to here
  double beam_half_angle = robot::kRobuter.ring.half_angle;  // rad, the ring cone marked (0: axis only)
  double pan_far = 2.491;              // m, a pan-tilt reading at or beyond this is "no echo"
  double follow_range = 1.5;           // m, prefix of the path followed before a new scan
  double goal_tolerance = 0.10;        // m
  std::int32_t drive_cm_s = 20;        // cm/s, fastest wheel driving
  std::int32_t turn_cm_s = 10;         // cm/s, fastest wheel turning in place
  std::uint32_t wheel_base_mm = 600;   // mm, DBW
  // Work per activation (not configured: what keeps an activation near 2 ms CPU here).
  std::uint32_t field_cells_per_run = 25000;  // cells of a new goal's cost field settled (~12 per µs:
                                              // the default window's 102,400 take 5 activations)
  std::uint32_t search_pops_per_run = 16000;  // states of a search popped (~10 per µs; a page of
                                              // states never written before counts 256)
  std::uint32_t tree_pops_per_run = 8000;     // states of the kept tree popped (its pages are mostly
                                              // new: 20,000 took 4-6.5 ms in the seed 000 lab run)
};

// What the planner reads of its neighbours' sections, handed over by the firmware's composition.
struct PlannerNeighbours {
  std::uint32_t pan_far_mm = PanTiltConfig{}.cap_mm;  // ptu.cap_mm: a pan-tilt reading at or beyond this is "no echo", mm
  bool cross_doors = PlacesConfig{}.cross_doors;      // places.cross_doors: at a narrow door, lend the robot to the doors
};

// Why: one place turns the configuration's mm and counts into the planner's m and cells: its
// section, the robot model (body, mounts, wheel base, top speed) and the pan-tilt's far reading.
PlannerSettings make_settings(const PlannerModuleConfig& p, const robot::RobotModel& m,
                              std::uint32_t pan_far_mm = PlannerNeighbours{}.pan_far_mm);

}  // namespace robuter::planner
