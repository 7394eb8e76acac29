// SPDX-License-Identifier: GPL-3.0-or-later
// The odometry motion model (motion_model.hpp).
#include "modules/localise/lib/motion_model.hpp"

#include <cmath>
#include <numbers>

namespace robuter::loc {

OdometryStep odometry_step(const Pose& before, const Pose& after) {
  const double dx = after.x() - before.x(), dy = after.y() - before.y();
  OdometryStep s;
  s.trans = std::hypot(dx, dy);
  s.rot1 = s.trans < 1e-4 ? 0.0 : wrap_angle(std::atan2(dy, dx) - before.z());
  if (std::abs(s.rot1) > 0.5 * std::numbers::pi) {  // backwards: the shorter first rotation
    s.rot1 = wrap_angle(s.rot1 + std::numbers::pi);
    s.trans = -s.trans;
  }
  s.rot2 = wrap_angle(after.z() - before.z() - s.rot1);
  return s;
}

Pose sample_motion(const Pose& pose, const OdometryStep& step, const MotionNoise& noise, std::mt19937_64& rng) {
  std::normal_distribution<double> unit(0.0, 1.0);
  const double t = std::abs(step.trans);
  // The rotations' noise counts the smaller way round, as AMCL does (a reverse is no half turn).
  const double r1 = std::min(std::abs(step.rot1), std::abs(std::numbers::pi - std::abs(step.rot1)));
  const double r2 = std::min(std::abs(step.rot2), std::abs(std::numbers::pi - std::abs(step.rot2)));
  const double rot1 = step.rot1 - std::sqrt(noise.rot_from_rot * r1 * r1 + noise.rot_from_trans * t * t) * unit(rng);
  const double trans = step.trans - std::sqrt(noise.trans_from_trans * t * t +
                                              noise.trans_from_rot * (r1 * r1 + r2 * r2)) * unit(rng);
  const double rot2 = step.rot2 - std::sqrt(noise.rot_from_rot * r2 * r2 + noise.rot_from_trans * t * t) * unit(rng);
  return move_pose(pose, OdometryStep{rot1, trans, rot2});
}

Pose move_pose(const Pose& pose, const OdometryStep& step) {
  const double heading = pose.z() + step.rot1;
  return Pose(pose.x() + step.trans * std::cos(heading), pose.y() + step.trans * std::sin(heading),
              wrap_angle(heading + step.rot2));
}

}  // namespace robuter::loc
