// SPDX-License-Identifier: GPL-3.0-or-later
// Basic value types of the simulated world: planar vectors, poses, angles and unit conversions.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <numbers>

#include "robot/angles.hpp"

namespace robuter::sim {

using Vec2 = Eigen::Vector2d;  // a point or direction in the plane, m

// A planar pose: the robot's wheel-axle midpoint and heading in the world frame.
struct Pose {
  double x = 0.0;      // position along the world x axis, m
  double y = 0.0;      // position along the world y axis, m
  double theta = 0.0;  // heading, rad, counter-clockwise from the world x axis
};

// Both drive wheels' linear speeds (tread speed over the floor).
struct WheelSpeeds {
  double left = 0.0;   // left wheel, m/s (positive drives the robot forward)
  double right = 0.0;  // right wheel, m/s
};

constexpr double kPi = std::numbers::pi;

// Degrees to radians: configuration files speak degrees, the model speaks radians.
constexpr double deg_to_rad(double deg) { return deg * kPi / 180.0; }

// Radians to degrees, for messages and documents.
constexpr double rad_to_deg(double rad) { return rad * 180.0 / kPi; }

// The firmware's wheel speeds are integer cm/s; the model works in m/s.
constexpr double cm_per_s_to_m_per_s(double cm_s) { return cm_s * 0.01; }

// Folds an angle into (-pi, pi] so headings compare and print sensibly (robot/angles.hpp: one rule).
using robot::wrap_angle;

// The pose's heading as a unit vector.
inline Vec2 heading_vector(const Pose& p) { return {std::cos(p.theta), std::sin(p.theta)}; }

// Maps a point given in the robot frame (x forward, y left) to the world frame.
inline Vec2 to_world(const Pose& p, const Vec2& local) {
  const double c = std::cos(p.theta), s = std::sin(p.theta);
  return {p.x + c * local.x() - s * local.y(), p.y + s * local.x() + c * local.y()};
}

// Maps a world point into the robot frame of pose `p`.
inline Vec2 to_local(const Pose& p, const Vec2& world) {
  const double c = std::cos(p.theta), s = std::sin(p.theta);
  const double dx = world.x() - p.x, dy = world.y() - p.y;
  return {c * dx + s * dy, -s * dx + c * dy};
}

}  // namespace robuter::sim
