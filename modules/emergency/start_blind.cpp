// SPDX-License-Identifier: GPL-3.0-or-later
// The start pose's blind set: the near field and the gaps between the cones that read at rest.
#include "modules/emergency/start_blind.hpp"

#include <algorithm>
#include <cmath>

#include "robot/model_geometry.hpp"
#include "robot/robot_model.hpp"

namespace robuter::emergency {

void StartBlind::observe(std::uint64_t tick, const Pose2& now, bool at_rest, std::uint32_t scans,
                         const std::uint64_t* read_tick, int sensors) {
  if (!at_rest) {
    resting_ = false;  // moving: the start pose, if any, stays for the start's first metres
    if (valid_ && (now.p - start_.p).norm() > s_.travel) valid_ = false;
    return;
  }
  if (!resting_) {
    resting_ = true;
    valid_ = false;  // a new rest: a new start pose once the ring has looked around it
    rest_tick_ = tick;
    rest_scans_ = scans;
    return;
  }
  if (valid_ || scans - rest_scans_ < s_.scans) return;
  fired_ = 0;
  for (int i = 0; i < sensors && i < 32; ++i)
    if (read_tick[i] > rest_tick_) fired_ |= 1u << i;
  start_ = now;
  valid_ = true;
}

void StartBlind::reset() {
  resting_ = false;
  valid_ = false;
}

bool StartBlind::covers(const Eigen::Vector2d& p) const {
  if (!valid_) return false;
  const Eigen::Vector2d l = to_body(start_, p);
  const Eigen::Vector2d e = s_.outside(l.x(), l.y());
  const double out = std::hypot(e.x(), e.y());
  if (out <= s_.near) return true;
  if (out > s_.wedge_reach) return false;
  const auto& ring = robot::kRobuter.ring;
  for (int s = 1; s <= robot::kRingSensors; ++s) {
    if (!(fired_ & (1u << (s - 1)))) continue;
    const robot::SonarMount& m = ring.sensor(s).mount;
    const Eigen::Vector2d v = l - robot::position(m);
    if (v.squaredNorm() < (ring.blanking + s_.edge) * (ring.blanking + s_.edge)) continue;
    // Inside a cone that read, farther than a cell from its edges (r·sin(half − off), written
    // with the axis components): it was certified or shadowed.
    const Eigen::Vector2d a = robot::axis(m);
    const double along = v.dot(a), across = std::abs(a.x() * v.y() - a.y() * v.x());
    if (std::sin(ring.half_angle) * along - std::cos(ring.half_angle) * across >= s_.edge) return false;
  }
  return true;
}

}  // namespace robuter::emergency
