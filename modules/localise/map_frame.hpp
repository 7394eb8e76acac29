// SPDX-License-Identifier: GPL-3.0-or-later
// The robot's pose on its map: the odometry's posture carried by the localisation's correction.
#pragma once

#include <Eigen/Geometry>

#include "modules/executor/posture_units.hpp"
#include "modules/topics.hpp"

namespace robuter::localise {

// The one place the odometry frame and the map frame are composed (docs/LOCALISATION.md, "The
// map frame"). The correction is the pose pair in `l`: the map pose (map_x, map_y, map_theta) of
// the odometry posture (odo_x, odo_y, odo_theta). While no localisation runs (state off, or the
// topic never published) the map frame is the odometry frame, as it always was. Nor is it while
// the correction belongs to an odometry an AC has since replaced (`odometry_seq`, Posture's):
// AC sets the map pose where it sets the odometry, which the module's next run confirms.
bool corrects(const Localisation& l, std::uint32_t odometry_seq);
// The map pose of odometry posture `p` (of the odometry `odometry_seq`).
executor::PostureUnits map_posture(const executor::PostureUnits& p, const Localisation& l, std::uint32_t odometry_seq);
// The odometry posture of map pose `m` (AW: the executor drives in the odometry frame).
executor::PostureUnits odometry_posture(const executor::PostureUnits& m, const Localisation& l, std::uint32_t odometry_seq);
// The correction as a rigid transform: a point of the odometry frame `odometry_seq` to the map
// frame (identity while the map frame is the odometry frame). The safety core's known structure
// (modules/firmware/prior_structure.hpp) places the map with it.
Eigen::Isometry2d map_from_odometry(const Localisation& l, std::uint32_t odometry_seq);
// The map pose of the posture the executor published.
inline executor::PostureUnits map_posture(const Posture& p, const Localisation& l) {
  return map_posture(executor::PostureUnits{p.x, p.y, p.theta}, l, p.odometry_seq);
}

}  // namespace robuter::localise
