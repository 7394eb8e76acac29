// SPDX-License-Identifier: GPL-3.0-or-later
// The body's rectangle about the wheel axle and the blind near field around it, as the safety core sees them.
#pragma once

#include <Eigen/Core>
#include <algorithm>

namespace robuter::emergency {

// The body the swept envelope and the start's blind set are built from (robot frame: x ahead of
// the wheel axle, y to the left).
struct BodyBox {
  double front = 0.695;       // wheel axle to the front face, m
  double rear = 0.330;        // wheel axle to the rear face, m
  double half_width = 0.350;  // half the body's width, m
  double near = 0.15;         // depth of the blind near field around the body (the blanking range), m

  // How far the point (x, y) of the robot frame (m) lies outside the rectangle, along each axis
  // (0, 0: under the body), m.
  Eigen::Vector2d outside(double x, double y) const {
    return {std::max({-rear - x, 0.0, x - front}), std::max({-half_width - y, 0.0, y - half_width})};
  }
};

}  // namespace robuter::emergency
