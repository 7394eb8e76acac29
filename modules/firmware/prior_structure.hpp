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
// move the walls, and a point is on structure within the estimate's uncertainty too: half a map
// cell, plus twice its 1-sigma ellipse's semi-major axis, plus twice its heading's sigma times the
// point's distance from the robot, at most kMaxSlack. A map placed by an estimate a few
// centimetres and a degree off explains no echo at the quarter cell the exact frame allows (a
// jamb's corner 2.48 m away at a cone's edge lay 12 cm from the arc: docs/SAFETY.md §13).
class PriorMapStructure final : public emergency::KnownStructure {
 public:
  PriorMapStructure(plan::OccupancyMap map, Reader<Localisation> localisation, Reader<Posture> posture);
  void update() override;
  // On an occupied cell, or within a quarter cell of one (a face on a cell boundary echoes from
  // either side of it), or within the slack of one while a localisation places the map.
  bool occupied(const Eigen::Vector2d& p) const override;

  static constexpr double kMaxSlack = 0.15;  // m: the most the estimate's uncertainty widens the test

 private:
  plan::OccupancyMap map_;                                       // the a-priori map, as loaded
  loc::DistanceField field_;                                     // its distance field (to kMaxSlack)
  Reader<Localisation> localisation_;                            // the map frame's correction
  Reader<Posture> posture_;                                      // which odometry it corrects
  Eigen::Isometry2d to_map_ = Eigen::Isometry2d::Identity();     // map ← odometry, at the last update()
  double slack_ = 0.0;                                           // m at the robot, 0 while the frames are one
  Eigen::Vector2d robot_ = Eigen::Vector2d::Zero();              // the axle, odometry frame, m, at the last update()
  double turn_slack_ = 0.0;                                      // m more per m from the robot
};

}  // namespace robuter
