// SPDX-License-Identifier: GPL-3.0-or-later
// The map frame (map_frame.hpp): rigid transforms in the plane with Eigen.
#include "modules/localise/map_frame.hpp"

namespace robuter::localise {
namespace {

Eigen::Isometry2d isometry(const executor::PostureUnits& p) {
  Eigen::Isometry2d t = Eigen::Isometry2d::Identity();
  t.translate(Eigen::Vector2d(executor::tenth_mm_to_metres(p.x), executor::tenth_mm_to_metres(p.y)));
  t.rotate(executor::centideg_to_radians(p.theta));
  return t;
}

executor::PostureUnits posture(const Eigen::Isometry2d& t) {
  const Eigen::Vector2d x = t.translation();
  const Eigen::Matrix2d r = t.linear();
  return {executor::metres_to_tenth_mm(x.x()), executor::metres_to_tenth_mm(x.y()),
          executor::radians_to_centideg(std::atan2(r(1, 0), r(0, 0)))};
}

// map ← odometry: the map pose of the reference times the inverse of its odometry posture.
Eigen::Isometry2d correction(const Localisation& l) {
  return isometry({l.map_x, l.map_y, l.map_theta}) * isometry({l.odo_x, l.odo_y, l.odo_theta}).inverse();
}

}  // namespace

bool corrects(const Localisation& l, std::uint32_t odometry_seq) {
  return l.state != LocaliseState::off && l.odometry_seq == odometry_seq;
}

Eigen::Isometry2d map_from_odometry(const Localisation& l, std::uint32_t odometry_seq) {
  return corrects(l, odometry_seq) ? correction(l) : Eigen::Isometry2d::Identity();
}

executor::PostureUnits map_posture(const executor::PostureUnits& p, const Localisation& l, std::uint32_t odometry_seq) {
  if (!corrects(l, odometry_seq)) return p;
  return posture(correction(l) * isometry(p));
}

executor::PostureUnits odometry_posture(const executor::PostureUnits& m, const Localisation& l, std::uint32_t odometry_seq) {
  if (!corrects(l, odometry_seq)) return m;
  return posture(correction(l).inverse() * isometry(m));
}

}  // namespace robuter::localise
