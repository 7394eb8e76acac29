// SPDX-License-Identifier: GPL-3.0-or-later
// Turn-then-drive legs with proportional control, as the go-to (AW) does, but in both directions.
#include "modules/planner/path_follower.hpp"

#include <algorithm>
#include <cmath>

#include "robot/angles.hpp"
#include "robot/wheel_speed.hpp"

namespace robuter::planner {

namespace {
using robot::wrap_angle;  // (−π, π]: robot/angles.hpp
using robot::wheel_command;  // whole cm/s within lo..hi: robot/wheel_speed.hpp
}  // namespace

void PathFollower::start(std::span<const Leg> legs) {
  count_ = std::min(legs.size(), legs_.size());
  std::copy_n(legs.begin(), count_, legs_.begin());
  index_ = 0;
  driving_ = false;
}

// Positive error = counter-clockwise = right wheel forward, left wheel back.
Wheels PathFollower::turn(double error) const {
  const double half_base_cm = static_cast<double>(s_.wheel_base_mm) / 20.0;
  const std::int32_t w = wheel_command(s_.turn_gain * error * half_base_cm, s_.min_cm_s, s_.max_turn_cm_s);
  return {-w, w};
}

// The turn uses the unwrapped heading, so a path that turns the long way round is obeyed; the
// drive steers towards the leg's end (facing it, or facing away when backing) and ends when the
// end is reached or passed along the leg.
Wheels PathFollower::step(const plan::Pose2& now) {
  while (index_ < count_) {
    const Leg& leg = legs_[index_];
    if (!driving_) {
      const double err = leg.heading - now.heading;
      if (std::abs(err) > s_.angle_tolerance) return turn(err);
      driving_ = true;
    }
    if (!leg.drive) {
      ++index_;
      driving_ = false;
      continue;
    }
    const double sign = leg.forward ? 1.0 : -1.0;
    const double ux = sign * std::cos(leg.heading), uy = sign * std::sin(leg.heading);
    const double ex = leg.end.x - now.x, ey = leg.end.y - now.y;
    const double along = ex * ux + ey * uy;  // m left along the leg
    if (along <= s_.position_tolerance) {
      ++index_;
      driving_ = false;
      continue;
    }
    // Face the end (or away from it when backing); a large error stops to turn again.
    const double facing = std::atan2(ey, ex) + (leg.forward ? 0.0 : plan::kPi);
    const double err = wrap_angle(facing - now.heading);
    if (std::abs(err) > s_.reorient_angle && along > 0.05) return turn(err);
    const double v = sign * std::clamp(s_.drive_gain * along * 100.0, static_cast<double>(s_.min_cm_s),
                                       static_cast<double>(s_.max_drive_cm_s));  // cm/s
    const double w = s_.heading_gain * err * static_cast<double>(s_.wheel_base_mm) / 20.0;  // cm/s
    const double hi = s_.max_drive_cm_s;
    return {static_cast<std::int32_t>(std::lround(std::clamp(v - w, -hi, hi))),
            static_cast<std::int32_t>(std::lround(std::clamp(v + w, -hi, hi)))};
  }
  return {0, 0};
}

}  // namespace robuter::planner
