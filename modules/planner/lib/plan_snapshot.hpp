// SPDX-License-Identifier: GPL-3.0-or-later
// A plan copied for a picture: the map's cells, the expanded obstacles, the path, start and goal.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "modules/planner/lib/planner.hpp"

namespace robuter::plan {

// Everything a picture of one plan shows, in plain arrays sized once (reserve), so that a
// real-time caller can fill it (capture) without allocating and hand it to another thread.
struct PlanSnapshot {
  // Per cell: the map's state in bits 0-1 (CellState), and in bits 2-3 how many footprint
  // layers block the cell: 0 none, 1 some (the rectangle fits at some headings), 2 all.
  static constexpr std::uint8_t kSomeBlocked = 1u << 2;
  static constexpr std::uint8_t kAllBlocked = 2u << 2;

  MapGeometry geometry;                  // cells, m per cell, origin (m)
  std::vector<std::uint8_t> cells;       // width × height, row y = 0 first (see above)
  std::vector<std::uint16_t> blocked;    // scratch of capture(): blocking layers per cell, count
  std::vector<Waypoint> path;            // capacity: the longest path kept
  std::size_t path_len = 0;              // waypoints used in `path`
  bool path_truncated = false;           // the plan had more waypoints than `path` holds
  std::size_t prefix_len = 0;            // leading waypoints the robot follows before the next scan
  FootprintKind footprint = FootprintKind::Disc;  // what the layers expand
  RectangleFootprint rectangle{};        // m, the body (Rectangle)
  double radius = 0.0;                   // m, the disc (Disc)
  Pose2 start{};                         // m, rad: where the plan started
  Point2 goal{};                         // m
  PlanStatus status = PlanStatus::Unreachable;  // the plan's outcome
  double length = 0.0;                   // m, the path's length (0 without a path)
  std::uint32_t goal_seq = 0;            // which goal (the firmware's XG sequence; 0 for tools)
  std::uint32_t plan_number = 0;         // 1 = the first plan for this goal, then the replans
  std::uint64_t tick = 0;                // kernel tick of the plan (0 for tools)

  // Why: the allocation point: sizes the cell array for `planner`'s map and the path for
  // `max_path` waypoints.
  void reserve(const Planner& planner, std::size_t max_path);
  // Why: copies `planner`'s map, layers and last path (the outcome `result` from `start` to
  // `goal`) into the reserved arrays; allocates nothing. False if the map's size changed since
  // reserve (nothing is copied then).
  bool capture(const Planner& planner, const PlanResult& result, const Pose2& start, Point2 goal);
};

}  // namespace robuter::plan
