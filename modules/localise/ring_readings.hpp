// SPDX-License-Identifier: GPL-3.0-or-later
// The ring's ranges as the filter's readings, each placed where the robot was when it was read.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "modules/emergency/pose_history.hpp"
#include "modules/localise/lib/particle_filter.hpp"
#include "modules/topics.hpp"
#include "robot/robot_model.hpp"

namespace robuter::localise {

// The odometry posture (0.1 mm, 0.01°) as the filter's pose (m, m, rad).
loc::Pose to_pose(std::int32_t x, std::int32_t y, std::int32_t theta);

// Collects the ring's ranges read since the last step (per sensor, by read tick; a sensor that
// heard nothing as a silence within the firing's reach, SonarReading::silence) and at most
// kMaxAgeTicks before the history's last posture, as readings in the robot frame of odometry pose
// `now`, each from the pose the history gives for its read tick (the safety core's PoseHistory:
// interpolated between the executor's postures, extrapolated past the last): a range read 0.2 s
// earlier came from a transducer 8 cm back along the path at 0.4 m/s, and says so.
class RingReadings {
 public:
  static constexpr std::uint64_t kMaxAgeTicks = 150;  // within the history's 16 postures (1.6 s)
  explicit RingReadings(const robot::Ring& ring);
  // Into `out` (at most out.size()); returns how many.
  std::size_t collect(const UltrasonicRanges& ranges, const emergency::PoseHistory& history, const loc::Pose& now,
                      std::span<loc::SonarReading> out);
  // A step took the ranges collected: the next one uses only ranges read after them.
  void mark_used(const UltrasonicRanges& ranges);

 private:
  std::array<loc::SonarReading, kSensors> mount_{};  // each sensor's mount and axis, robot frame
  std::array<std::uint64_t, kSensors> used_tick_{};  // the read tick of each sensor's last range used
};

}  // namespace robuter::localise
