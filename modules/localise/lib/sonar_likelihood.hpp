// SPDX-License-Identifier: GPL-3.0-or-later
// How likely one sonar range is from a given pose, on the distance field of the robot's map.
#pragma once

#include <array>

#include <Eigen/Core>

#include "modules/localise/lib/distance_field.hpp"

namespace robuter::loc {

// The sonar model's constants (docs/LOCALISATION.md, "The sonar model").
struct SonarModelParams {
  double half_angle = 0.218;     // beam cone half-angle, rad (the ring's 12.5°)
  double max_range = 4.9;        // readings at or past this carry no echo, m
  double min_range = 0.15;       // blanking: readings nearer than this are not ranges, m
  double sigma_hit = 0.08;       // spread of an echo about the nearest mapped surface, m
  double z_hit = 0.75;           // weight of "the echo came off the map's surface"
  double z_rand = 0.25;          // weight of anything else (cross-talk, people, unmapped things)
  double through_weight = 0.35;  // factor when the beam's axis crosses a mapped wall short of the range
  int arc_samples = 5;           // points across the cone at the range (odd: one on the axis)
};

// One range reading in the robot's frame.
struct SonarReading {
  Eigen::Vector2d mount = Eigen::Vector2d::Zero();  // transducer ahead of / left of the axle midpoint, m
  double direction = 0.0;                           // beam axis, rad, counter-clockwise from forward
  double range = 0.0;                               // measured range, m (0 or >= max_range: no echo)
};

// True when the reading says where a surface is (an echo inside the model's range); a missing
// echo says nothing to this model: a specular surface loses the echo as surely as open space.
bool informative(const SonarReading& reading, const SonarModelParams& params);

// The directions across the cone the arc is read at, relative to the axis (cos, sin), worked
// out once from the params: no trigonometry per particle.
struct ArcTable {
  static constexpr int kMax = 9;              // most points across the cone
  std::array<Eigen::Vector2d, kMax> offsets;  // (cos, sin) of each point's angle off the axis
  int count = 0;                              // points in use
};
ArcTable arc_table(const SonarModelParams& params);

// The likelihood of an informative reading for a sensor at `origin` looking along the unit
// vector `axis` (world frame), up to a constant factor shared by every pose: a mixture of an
// echo off the map (the nearest mapped surface to the arc of radius `range` across the cone,
// Gaussian) and a uniform rest; times `through_weight` when the axis crosses a mapped wall well
// short of the range (the beam would have echoed there).
double sonar_likelihood(const DistanceField& field, const Eigen::Vector2d& origin, const Eigen::Vector2d& axis,
                        double range, const SonarModelParams& params, const ArcTable& arc);

}  // namespace robuter::loc
