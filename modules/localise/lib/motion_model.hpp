// SPDX-License-Identifier: GPL-3.0-or-later
// The odometry motion model: how far a particle moves for one odometry increment, with noise.
#pragma once

#include <random>

#include <Eigen/Core>

#include "robot/angles.hpp"

namespace robuter::loc {

// A planar pose (x, y in m; theta in rad, counter-clockwise).
using Pose = Eigen::Vector3d;

// Noise as in Thrun, Burgard and Fox's sample_motion_model_odometry (and Nav2's AMCL "diff"
// model): each part's variance is a1·rot² + a2·trans² (rotations) or a3·trans² + a4·rot²
// (travel), so each part gets noise from both its own size and the other's. Applied once per
// filter step (the odometry accumulated since the last), not per tick.
struct MotionNoise {
  double rot_from_rot = 0.05;      // alpha1: rotation variance per rad² turned
  double rot_from_trans = 0.005;   // alpha2: rotation variance (rad²) per m² driven
  double trans_from_trans = 0.005; // alpha3: travel variance per m² driven
  double trans_from_rot = 0.005;   // alpha4: travel variance (m²) per rad² turned
};

// An odometry increment as rotate, translate, rotate; driving backwards is a translation < 0.
struct OdometryStep {
  double rot1 = 0.0;   // rad
  double trans = 0.0;  // m
  double rot2 = 0.0;   // rad
};

// The increment between two odometry poses (same frame).
OdometryStep odometry_step(const Pose& before, const Pose& after);

// `pose` moved by `step` with noise drawn from `rng`.
Pose sample_motion(const Pose& pose, const OdometryStep& step, const MotionNoise& noise, std::mt19937_64& rng);
// `pose` moved by `step` exactly (sample_motion() moves it by a step with the noise added).
Pose move_pose(const Pose& pose, const OdometryStep& step);

// An angle in (-pi, pi] (robot/angles.hpp: one rule for the firmware and the simulator).
using robot::wrap_angle;

}  // namespace robuter::loc
