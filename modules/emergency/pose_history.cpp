// SPDX-License-Identifier: GPL-3.0-or-later
// Pose history: arcs between postures, a jump test for a set odometry.
#include "modules/emergency/pose_history.hpp"

#include <cmath>
#include <numbers>

#include "robot/angles.hpp"

namespace robuter::emergency {

namespace {
using robot::wrap_angle;  // (−π, π]: robot/angles.hpp (this file's loop ran for ever on a huge angle)
}  // namespace

// Exact arc for a constant twist (a straight line when the turn rate is negligible).
Pose2 advance(const Pose2& pose, double v, double w, double t) {
  Pose2 out;
  const double dth = w * t;
  if (std::abs(dth) < 1e-9) {
    out.p = pose.p + v * t * Eigen::Vector2d(std::cos(pose.theta), std::sin(pose.theta));
  } else {
    const double r = v / w;
    out.p = pose.p + r * Eigen::Vector2d(std::sin(pose.theta + dth) - std::sin(pose.theta),
                                         -std::cos(pose.theta + dth) + std::cos(pose.theta));
  }
  out.theta = wrap_angle(pose.theta + dth);
  return out;
}

bool PoseHistory::add(std::uint64_t tick, const Pose2& pose, double max_step, double max_turn) {
  if (count_ > 0) {
    Sample& last = samples_[(head_ + kSamples - 1) % kSamples];
    if (tick < last.tick) {
      clear();
    } else {
      const double dt = static_cast<double>(tick - last.tick) + 1.0;
      if ((pose.p - last.pose.p).norm() > max_step * dt || std::abs(wrap_angle(pose.theta - last.pose.theta)) > max_turn * dt) {
        clear();
        samples_[head_] = {tick, pose};
        head_ = (head_ + 1) % kSamples;
        count_ = 1;
        return false;
      }
      if (tick == last.tick) {
        last.pose = pose;
        return true;
      }
    }
  }
  samples_[head_] = {tick, pose};
  head_ = (head_ + 1) % kSamples;
  if (count_ < kSamples) ++count_;
  return true;
}

std::uint64_t PoseHistory::last_tick() const { return count_ ? nth(count_ - 1).tick : 0; }

Twist2 PoseHistory::velocity() const {
  if (count_ < 2) return {};
  const Sample& a = nth(count_ - 2);
  const Sample& b = nth(count_ - 1);
  const double dt = static_cast<double>(b.tick - a.tick);
  const Eigen::Vector2d d = b.pose.p - a.pose.p;
  const double mid = a.pose.theta + 0.5 * wrap_angle(b.pose.theta - a.pose.theta);
  // Signed along the mean heading: a robot backing up has a negative speed.
  const double along = d.x() * std::cos(mid) + d.y() * std::sin(mid);
  return {along / dt, wrap_angle(b.pose.theta - a.pose.theta) / dt};
}

Pose2 PoseHistory::at(std::uint64_t tick) const {
  if (count_ == 0) return {};
  if (tick <= nth(0).tick) return nth(0).pose;
  const Sample& last = nth(count_ - 1);
  if (tick >= last.tick) {
    const Twist2 t = velocity();
    return advance(last.pose, t.v, t.w, static_cast<double>(tick - last.tick));
  }
  for (std::size_t i = count_ - 1; i > 0; --i) {
    const Sample& a = nth(i - 1);
    const Sample& b = nth(i);
    if (tick < a.tick) continue;
    const double f = static_cast<double>(tick - a.tick) / static_cast<double>(b.tick - a.tick);
    Pose2 out;
    out.p = a.pose.p + f * (b.pose.p - a.pose.p);
    out.theta = wrap_angle(a.pose.theta + f * wrap_angle(b.pose.theta - a.pose.theta));
    return out;
  }
  return nth(0).pose;
}

}  // namespace robuter::emergency
