// SPDX-License-Identifier: GPL-3.0-or-later
// Differential-drive motion: synchronised acceleration ramps, exact arcs per sub-step, contact
// search by bisection, and encoder odometry with optional seeded scale, noise and slip errors.
#include "hal/sim/robot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace robuter::sim {

namespace {
// Contact poses are found to this precision of body-point travel, m.
constexpr double kContactResolution = 1e-5;
}  // namespace

// Pre-sizes every buffer so that step() never allocates.
Robot::Robot(const World& world, const RobotParams& params, const Pose& start)
    : world_(world), params_(params), trail_(params.trail_capacity), rng_(params.odometry.seed) {
  scratch_.prepare(world_.segments().size());
  const Box b = params_.geometry.body();
  corner_radius_ = std::max({b.lo.norm(), b.hi.norm(), Vec2(b.lo.x(), b.hi.y()).norm(),
                             Vec2(b.hi.x(), b.lo.y()).norm()});
  place(start);
}

// Clamping here means the limit holds whatever the caller sends.
void Robot::command(const WheelSpeeds& speeds) {
  const double m = params_.limits.max_wheel_speed;
  command_.left = std::clamp(speeds.left, -m, m);
  command_.right = std::clamp(speeds.right, -m, m);
}

// The firmware speaks integer cm/s; convert once at the boundary.
void Robot::command_cm_s(double left, double right) {
  command({cm_per_s_to_m_per_s(left), cm_per_s_to_m_per_s(right)});
}

// A scenario reset: at rest, odometry agrees with the truth, trail restarts here.
void Robot::place(const Pose& pose) {
  pose_ = pose;
  pose_.theta = wrap_angle(pose_.theta);
  odom_ = pose_;
  actual_ = {};
  command_ = {};
  blocked_ = false;
  trail_.clear();
  last_trail_ = {pose_.x, pose_.y};
  trail_.push(last_trail_);
  bumper_ = footprint_hits(world_, params_.geometry, pose_, params_.contact_tolerance, scratch_);
}

// |v| plus the rotation speed of the farthest body corner.
double Robot::max_point_speed(double left, double right) const {
  const double v = 0.5 * (left + right);
  const double w = (right - left) / params_.geometry.wheel_base;
  return std::abs(v) + std::abs(w) * corner_radius_;
}

// Both wheels ramp linearly and reach their targets together, so the path curvature during a
// ramp from rest is already the commanded one. A wheel whose speed grows in magnitude uses
// max_accel, one that slows uses max_decel; a sign reversal uses max_accel throughout. Ramps
// are integrated in short sub-steps at their mean speeds (second-order accurate); constant
// speeds are integrated as exact arcs.
void Robot::step(double dt) {
  if (!(dt > 0.0)) return;
  time_ += dt;
  blocked_ = false;
  const auto& lim = params_.limits;
  auto rate = [&](double from, double to) {
    const bool speeding_up = std::abs(to) > std::abs(from) && from * to >= 0.0;
    const double r =
        speeding_up ? lim.max_accel : (from * to < 0.0 ? lim.max_accel : lim.max_decel);
    return r > 0.0 ? r : std::numeric_limits<double>::infinity();  // no limit: instant
  };
  const double l0 = actual_.left, r0 = actual_.right;
  const double dl = command_.left - l0, dr = command_.right - r0;
  const double ramp_time = std::max(std::abs(dl) / rate(l0, command_.left),
                                    std::abs(dr) / rate(r0, command_.right));
  double remaining = dt;
  bool moving = true;
  if (ramp_time > 0.0) {
    const double ramp = std::min(ramp_time, dt);
    const int n = std::max(1, static_cast<int>(std::ceil(ramp / params_.max_ramp_substep)));
    const double h = ramp / n;
    for (int i = 0; i < n && moving; ++i) {
      const double f = (static_cast<double>(i) + 0.5) * h / ramp_time;
      moving = advance(l0 + dl * f, r0 + dr * f, h);
    }
    if (moving) {
      const double f = ramp / ramp_time;
      actual_ = f >= 1.0 ? command_ : WheelSpeeds{l0 + dl * f, r0 + dr * f};
    }
    remaining -= ramp;
  } else {
    actual_ = command_;  // already there, or no acceleration limit
  }
  if (moving && remaining > 0.0 && (actual_.left != 0.0 || actual_.right != 0.0)) {
    moving = advance(actual_.left, actual_.right, remaining);
  }
  if (!moving) actual_ = {};
  bumper_ = footprint_hits(world_, params_.geometry, pose_, params_.contact_tolerance, scratch_);
}

// Splits tau so that no body point moves more than max_substep_travel between contact checks
// (far less than the body's 0.7 m, so no edge can be jumped). On a hit, bisects the sub-step to
// the last free pose and stops there.
bool Robot::advance(double left, double right, double tau) {
  const auto& od = params_.odometry;
  const double base = params_.geometry.wheel_base;
  const double travel = max_point_speed(left, right) * tau;
  const int n = std::max(1, static_cast<int>(std::ceil(travel / params_.max_substep_travel)));
  const double h = tau / n;
  const bool slips = od.slip_mean != 0.0 || od.slip_sigma != 0.0;
  for (int i = 0; i < n; ++i) {
    double lg = left, rg = right;
    if (slips) {
      lg *= 1.0 - std::clamp(od.slip_mean + od.slip_sigma * rng_.normal(), 0.0, 1.0);
      rg *= 1.0 - std::clamp(od.slip_mean + od.slip_sigma * rng_.normal(), 0.0, 1.0);
    }
    const double v = 0.5 * (lg + rg);
    const double w = (rg - lg) / base;
    const Pose next = integrate_arc(pose_, v, w, h);
    if (!footprint_hits(world_, params_.geometry, next, 0.0, scratch_)) {
      pose_ = next;
      travelled_ += std::abs(v) * h;
      integrate_odometry(left * h, right * h);
      record_trail();
      continue;
    }
    blocked_ = true;
    if (footprint_hits(world_, params_.geometry, pose_, 0.0, scratch_)) return false;  // stuck
    const double span = std::max(max_point_speed(lg, rg) * h, kContactResolution);
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < 64 && (hi - lo) * span > kContactResolution; ++k) {
      const double mid = 0.5 * (lo + hi);
      if (footprint_hits(world_, params_.geometry, integrate_arc(pose_, v, w, mid * h), 0.0,
                         scratch_)) {
        hi = mid;
      } else {
        lo = mid;
      }
    }
    pose_ = integrate_arc(pose_, v, w, lo * h);
    travelled_ += std::abs(v) * lo * h;
    integrate_odometry(left * lo * h, right * lo * h);
    record_trail();
    return false;
  }
  return true;
}

// Encoders see the wheel's own travel (slip is invisible to them), scaled and noisy.
void Robot::integrate_odometry(double dl, double dr) {
  const auto& od = params_.odometry;
  double el = dl * (1.0 + od.scale_left);
  double er = dr * (1.0 + od.scale_right);
  if (od.noise > 0.0) {
    el += od.noise * std::sqrt(std::abs(dl)) * rng_.normal();
    er += od.noise * std::sqrt(std::abs(dr)) * rng_.normal();
  }
  const double believed = params_.odometry_wheel_base > 0.0 ? params_.odometry_wheel_base : params_.geometry.wheel_base;
  const double base = believed + od.wheel_base_error;
  odom_ = integrate_arc(odom_, 0.5 * (el + er), (er - el) / base, 1.0);
}

// Keeps the picture's trail light: one point per trail_spacing of travel.
void Robot::record_trail() {
  const Vec2 p(pose_.x, pose_.y);
  if ((p - last_trail_).norm() >= params_.trail_spacing) {
    trail_.push(p);
    last_trail_ = p;
  }
}

}  // namespace robuter::sim
