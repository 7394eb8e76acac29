// SPDX-License-Identifier: GPL-3.0-or-later
// A short history of the executor's odometry postures: the pose at any recent tick, and the velocity.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstdint>

namespace robuter::emergency {

// A pose in the odometry frame.
struct Pose2 {
  Eigen::Vector2d p = Eigen::Vector2d::Zero();  // axle midpoint, m
  double theta = 0.0;                           // heading, rad
};

// Speed along the heading and turn rate, per tick (the history's unit of time).
struct Twist2 {
  double v = 0.0;  // forward, m/tick
  double w = 0.0;  // counter-clockwise, rad/tick
};

// The robot frame point q of a robot at `pose`, in the odometry frame.
inline Eigen::Vector2d to_world(const Pose2& pose, const Eigen::Vector2d& q) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  return pose.p + Eigen::Vector2d(c * q.x() - s * q.y(), s * q.x() + c * q.y());
}
// The odometry frame point p in the frame of a robot at `pose` (the inverse of to_world).
inline Eigen::Vector2d to_body(const Pose2& pose, const Eigen::Vector2d& p) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const Eigen::Vector2d d = p - pose.p;
  return {c * d.x() + s * d.y(), -s * d.x() + c * d.y()};
}
// Where a robot at `pose` is after moving along the arc of (v, w) for `t` (same time unit).
Pose2 advance(const Pose2& pose, double v, double w, double t);

// The last kSamples postures of distinct ticks. Poses between two samples are interpolated,
// after the last one extrapolated along the arc of the last velocity (the executor publishes
// every 10 ticks; a reading is taken in between). No heap.
class PoseHistory {
 public:
  static constexpr std::size_t kSamples = 16;  // samples kept, count

  // Adds the posture of `tick`; a second posture of the same tick replaces the first. Returns
  // false, after forgetting the history, when the pose jumped farther than a robot moves
  // (`max_step` m and `max_turn` rad per tick): the odometry was set (AC).
  bool add(std::uint64_t tick, const Pose2& pose, double max_step, double max_turn);
  void clear() { count_ = 0; }
  bool empty() const { return count_ == 0; }
  // The pose at `tick` (the first sample's before it).
  Pose2 at(std::uint64_t tick) const;
  // The velocity between the last two samples (zero with fewer than two).
  Twist2 velocity() const;
  std::uint64_t last_tick() const;

 private:
  // One posture.
  struct Sample {
    std::uint64_t tick = 0;  // tick of the odometry read
    Pose2 pose;              // the posture
  };
  const Sample& nth(std::size_t i) const { return samples_[(head_ + kSamples - count_ + i) % kSamples]; }

  std::array<Sample, kSamples> samples_{};
  std::size_t head_ = 0;   // slot of the next sample
  std::size_t count_ = 0;  // samples held
};

}  // namespace robuter::emergency
