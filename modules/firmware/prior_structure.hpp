// SPDX-License-Identifier: GPL-3.0-or-later
// The planner's a-priori map as the safety core's known structure: where an echo is explained.
#pragma once

#include <Eigen/Geometry>

#include "kernel/blackboard.hpp"
#include "modules/emergency/evidence_grid.hpp"
#include "modules/localise/lib/distance_field.hpp"
#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/topics.hpp"

namespace robuter {

// A copy of the map as loaded ([planner] map_file), never the planner's live map (the ring's
// marks there are evidence, not structure), or the place graph's walls. The map is in the map
// frame; the safety core asks in the odometry frame. The two are one frame unless a
// localisation runs ([localise] enabled): then the map is placed by its correction
// (localise::map_from_odometry, read at each update()), so that the odometry's drift does not
// move the walls, and a point is on structure within the estimate's uncertainty too (twice its
// 1-sigma ellipse's semi-major axis, at most kMaxSlack): a map placed by an estimate a few
// centimetres off would explain no echo at the quarter cell the exact frame allows
// (docs/LOCALISATION.md, "The safety core's structure").
class PriorMapStructure final : public safety::KnownStructure {
 public:
  PriorMapStructure(plan::OccupancyMap map, Reader<Localisation> localisation, Reader<Posture> posture);
  void update() override;
  // On an occupied cell, or within a quarter cell of one (a face on a cell boundary echoes from
  // either side of it), or within the slack of one while a localisation places the map.
  bool occupied(const Eigen::Vector2d& p) const override;

  static constexpr double kMaxSlack = 0.10;  // m: the most the estimate's uncertainty widens the test
  double slack() const { return slack_; }    // m, as of the last update()

 private:
  plan::OccupancyMap map_;                                       // the a-priori map, as loaded
  loc::DistanceField field_;                                     // its distance field (to kMaxSlack)
  Reader<Localisation> localisation_;                            // the map frame's correction
  Reader<Posture> posture_;                                      // which odometry it corrects
  Eigen::Isometry2d to_map_ = Eigen::Isometry2d::Identity();     // map ← odometry, at the last update()
  double slack_ = 0.0;                                           // m, 0 while the frames are one
};

}  // namespace robuter
