// SPDX-License-Identifier: GPL-3.0-or-later
// Go-to-posture: three phases with proportional control and speed limits.
#include "modules/executor/go_to.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "robot/angles.hpp"
#include "robot/wheel_speed.hpp"

namespace robuter::executor {

namespace {
using robot::wrap_angle;  // (−π, π]: robot/angles.hpp
using robot::wheel_command;  // whole cm/s within lo..hi: robot/wheel_speed.hpp
}  // namespace

void GoToController::start(const PostureUnits& target) {
  target_ = target;
  target_.theta = wrap_centideg(target.theta);
  phase_ = GoToPhase::turn_to_target;
}

// Positive error = target counter-clockwise = right wheel forward, left wheel back.
WheelSpeeds GoToController::turn(double error_rad) const {
  const double half_base_cm = static_cast<double>(s_.wheel_base_mm) / 20.0;
  const std::int32_t w = wheel_command(s_.turn_gain * error_rad * half_base_cm, s_.min_cm_s, s_.max_turn_cm_s);
  return {-w, w};
}

// Phases fall through within one step so an arrival or a small error never costs a cycle.
WheelSpeeds GoToController::step(const PostureUnits& now) {
  const double dx = static_cast<double>(target_.x) - now.x, dy = static_cast<double>(target_.y) - now.y;
  const double dist = std::hypot(dx, dy);  // 0.1 mm
  const double heading = centideg_to_radians(now.theta);
  const double bearing_err = wrap_angle(std::atan2(dy, dx) - heading);
  const double angle_tol = centideg_to_radians(s_.angle_tolerance);
  const double reorient = centideg_to_radians(s_.reorient_angle);
  if (phase_ == GoToPhase::turn_to_target) {
    if (dist <= s_.position_tolerance) phase_ = GoToPhase::turn_to_heading;
    else if (std::abs(bearing_err) <= angle_tol) phase_ = GoToPhase::drive;
    else return turn(bearing_err);
  }
  if (phase_ == GoToPhase::drive) {
    if (dist <= s_.position_tolerance) {
      phase_ = GoToPhase::turn_to_heading;
    } else if (std::abs(bearing_err) > reorient) {
      phase_ = GoToPhase::turn_to_target;
      return turn(bearing_err);
    } else {
      const double v = std::clamp(s_.drive_gain * dist / 100.0, static_cast<double>(s_.min_cm_s),
                                  static_cast<double>(s_.max_drive_cm_s));  // cm/s
      const double w = s_.turn_gain * bearing_err * static_cast<double>(s_.wheel_base_mm) / 20.0;
      const double hi = s_.max_drive_cm_s;
      return {static_cast<std::int32_t>(std::lround(std::clamp(v - w, -hi, hi))),
              static_cast<std::int32_t>(std::lround(std::clamp(v + w, -hi, hi)))};
    }
  }
  if (phase_ == GoToPhase::turn_to_heading) {
    const double err = wrap_angle(centideg_to_radians(target_.theta) - heading);
    if (std::abs(err) <= angle_tol) phase_ = GoToPhase::done;
    else return turn(err);
  }
  return {0, 0};
}

}  // namespace robuter::executor
