// SPDX-License-Identifier: GPL-3.0-or-later
// The robot model's geometry as Eigen vectors: sensor positions and directions, body corners.
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "robot/robot_model.hpp"

namespace robuter::robot {

// Where a transducer sits in the robot frame, m.
inline Eigen::Vector2d position(const SonarMount& s) { return {s.x, s.y}; }
// The unit vector of its beam axis in the robot frame.
inline Eigen::Vector2d axis(const SonarMount& s) { return {std::cos(s.direction), std::sin(s.direction)}; }

// The body's rear-right and front-left corners in the robot frame, grown by `inflate` m, m.
inline Eigen::Vector2d min_corner(const Body& b, double inflate = 0.0) {
  return {-b.axle_to_rear() - inflate, -0.5 * b.width - inflate};
}
inline Eigen::Vector2d max_corner(const Body& b, double inflate = 0.0) {
  return {b.axle_to_front + inflate, 0.5 * b.width + inflate};
}

}  // namespace robuter::robot
