// SPDX-License-Identifier: GPL-3.0-or-later
// The planner's a-priori map as the safety core's known structure: where an echo is explained.
#pragma once

#include "modules/emergency/evidence_grid.hpp"
#include "modules/planner/lib/occupancy_map.hpp"

namespace robuter {

// A copy of the map as loaded ([planner] map_file), never the planner's live map (the ring's
// marks there are evidence, not structure). Odometry frame = the map's frame, as the planner's.
class PriorMapStructure final : public safety::KnownStructure {
 public:
  explicit PriorMapStructure(plan::OccupancyMap map) : map_(std::move(map)) {}
  // On an occupied cell, or within a quarter cell of one (a face on a cell boundary echoes from
  // either side of it).
  bool occupied(const Eigen::Vector2d& p) const override;

 private:
  plan::OccupancyMap map_;  // the a-priori map, as loaded
};

}  // namespace robuter
