// SPDX-License-Identifier: GPL-3.0-or-later
// The ring's ranges as readings (ring_readings.hpp).
#include "modules/localise/ring_readings.hpp"

#include <Eigen/Geometry>

#include "modules/executor/posture_units.hpp"

namespace robuter::localise {

loc::Pose to_pose(std::int32_t x, std::int32_t y, std::int32_t theta) {
  return loc::Pose(executor::tenth_mm_to_metres(x), executor::tenth_mm_to_metres(y), executor::centideg_to_radians(theta));
}

RingReadings::RingReadings(const robot::Ring& ring) {
  for (int s = 1; s <= kSensors; ++s) {
    const robot::SonarMount& m = ring.sensor(s).mount;
    mount_[static_cast<std::size_t>(s - 1)] = loc::SonarReading{Eigen::Vector2d(m.x, m.y), m.direction, 0.0};
  }
}

std::size_t RingReadings::collect(const UltrasonicRanges& ranges, const emergency::PoseHistory& history, const loc::Pose& now,
                                  std::span<loc::SonarReading> out) {
  std::size_t n = 0;
  const Eigen::Rotation2Dd to_now(-now.z());
  for (std::size_t k = 0; k < mount_.size() && n < out.size(); ++k) {
    const std::uint64_t t = ranges.read_tick[k];
    if (t == 0 || t <= used_tick_[k]) continue;  // never read, or used by an earlier step
    const bool echo = (ranges.no_echo & (1u << k)) == 0;
    if (ranges.mm[k] == 0 || history.empty() || t + kMaxAgeTicks < history.last_tick()) continue;
    // The pose it was read from, in the robot frame of `now`.
    const emergency::Pose2 at = history.at(t);
    const loc::Pose then(at.p.x(), at.p.y(), at.theta);
    const double turn = loc::wrap_angle(then.z() - now.z());
    const Eigen::Vector2d offset = to_now * Eigen::Vector2d(then.x() - now.x(), then.y() - now.y());
    const loc::SonarReading& m = mount_[k];
    out[n++] = loc::SonarReading{offset + Eigen::Rotation2Dd(turn) * m.mount, loc::wrap_angle(m.direction + turn),
                                 static_cast<double>(ranges.mm[k]) * 1e-3, !echo};  // a silence: none within mm
  }
  return n;
}

void RingReadings::mark_used(const UltrasonicRanges& ranges) { used_tick_ = ranges.read_tick; }

}  // namespace robuter::localise
