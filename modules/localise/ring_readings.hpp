// SPDX-License-Identifier: GPL-3.0-or-later
// The ring's ranges as the filter's readings, each placed where the robot was when it was read.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "modules/localise/lib/particle_filter.hpp"
#include "modules/topics.hpp"
#include "robot/robot_model.hpp"

namespace robuter::localise {

// The odometry postures of the last seconds (the executor publishes one every 100 ms), to carry
// a range read between two of them to the pose of the filter's step.
class PoseHistory {
 public:
  static constexpr std::size_t kSize = 32;  // samples kept (3.2 s at the executor's rate)
  void clear() { count_ = 0; }
  // A new sample (ticks increasing); the oldest goes when full.
  void push(std::uint64_t tick, const loc::Pose& odometry);
  bool empty() const { return count_ == 0; }
  std::uint64_t oldest_tick() const;
  // The odometry at `tick`, interpolated between the samples around it (the nearest end outside them).
  loc::Pose at(std::uint64_t tick) const;

 private:
  struct Sample {
    std::uint64_t tick = 0;  // when
    loc::Pose pose = loc::Pose::Zero();  // odometry, m, m, rad
  };
  const Sample& nth(std::size_t i) const { return samples_[(first_ + i) % kSize]; }  // 0 = oldest
  std::array<Sample, kSize> samples_{};
  std::size_t first_ = 0;  // the oldest sample's slot
  std::size_t count_ = 0;  // samples held
};

// The odometry posture (0.1 mm, 0.01°) as the filter's pose (m, m, rad).
loc::Pose to_pose(std::int32_t x, std::int32_t y, std::int32_t theta);

// Collects the ring's ranges read since the last step (per sensor, by read tick) that were read
// within the history's span, as readings in the robot frame of odometry pose `now`: a range read
// 0.2 s earlier came from a transducer 8 cm back along the path at 0.4 m/s, and says so.
class RingReadings {
 public:
  explicit RingReadings(const robot::Ring& ring);
  // Into `out` (at most out.size()); returns how many. Ranges older than the history are skipped.
  std::size_t collect(const UltrasonicRanges& ranges, const PoseHistory& history, const loc::Pose& now,
                      std::span<loc::SonarReading> out);
  // A step took the ranges collected: the next one uses only ranges read after them.
  void mark_used(const UltrasonicRanges& ranges);

 private:
  std::array<loc::SonarReading, kSensors> mount_{};  // each sensor's mount and axis, robot frame
  std::array<std::uint64_t, kSensors> used_tick_{};  // the read tick of each sensor's last range used
};

}  // namespace robuter::localise
