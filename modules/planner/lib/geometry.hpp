// SPDX-License-Identifier: GPL-3.0-or-later
// Small geometric value types shared by the planner library: world points, poses, grid cells.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>

namespace robuter::plan {

// A point in the world frame.
struct Point2 {
  double x = 0.0;  // m
  double y = 0.0;  // m
};

// A position and heading in the world frame.
struct Pose2 {
  double x = 0.0;        // m
  double y = 0.0;        // m
  double heading = 0.0;  // rad, counter-clockwise from +x
};

// Integer grid coordinates of a cell (column x, row y; y grows with world y).
struct Cell {
  int x = 0;  // cells
  int y = 0;  // cells
  friend bool operator==(const Cell&, const Cell&) = default;
};

// A cell plus a heading slice, the state of the (x, y, heading) search.
struct CellPose {
  int x = 0;      // cells
  int y = 0;      // cells
  int slice = 0;  // heading slice index in [0, slices)
  friend bool operator==(const CellPose&, const CellPose&) = default;
};

inline constexpr double kSqrt2 = std::numbers::sqrt2;
inline constexpr double kPi = std::numbers::pi;

// Why: the admissible and consistent heuristic of 8-connected grids with diagonal cost sqrt(2).
inline double octile(int dx, int dy) {
  const int ax = dx < 0 ? -dx : dx;
  const int ay = dy < 0 ? -dy : dy;
  const int lo = ax < ay ? ax : ay;
  const int hi = ax < ay ? ay : ax;
  return static_cast<double>(hi - lo) + kSqrt2 * static_cast<double>(lo);
}

// Why: headings are compared modulo a period (2 pi, or pi for a symmetric footprint).
inline double wrap_angle(double a, double period) {
  double r = std::fmod(a, period);
  if (r < 0.0) r += period;
  return r;
}

}  // namespace robuter::plan
