// SPDX-License-Identifier: GPL-3.0-or-later
// The CAN drive pair: unit conversions, odometry with Eigen, health from bus and drives, immediate RPDO1s.
#include "hal/linux/can/can_drive.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace robuter::hal::can {

WheelOdometry::WheelOdometry(std::uint32_t counts_per_rev, std::uint32_t wheel_diameter_mm,
                             std::uint32_t wheel_base_mm)
    : m_per_count_(std::numbers::pi * wheel_diameter_mm * 1e-3 / counts_per_rev),
      counts_per_cm_(counts_per_rev / (std::numbers::pi * wheel_diameter_mm * 0.1)),
      base_m_(wheel_base_mm * 1e-3) {}

std::int32_t WheelOdometry::counts_per_s(std::int32_t cm_s) const {
  const double c = std::round(cm_s * counts_per_cm_);
  constexpr double hi = std::numeric_limits<std::int32_t>::max(), lo = std::numeric_limits<std::int32_t>::min();
  return static_cast<std::int32_t>(std::clamp(c, lo, hi));
}

// Exact for a constant-curvature step when the heading change is small (10 ms ticks).
void WheelOdometry::advance(double left_m, double right_m) {
  const double ds = 0.5 * (left_m + right_m);
  const double dtheta = (right_m - left_m) / base_m_;
  position_ += Eigen::Rotation2Dd(theta_ + 0.5 * dtheta) * Eigen::Vector2d(ds, 0.0);
  theta_ = std::remainder(theta_ + dtheta, 2.0 * std::numbers::pi);
  if (theta_ <= -std::numbers::pi) theta_ += 2.0 * std::numbers::pi;
}

Odometry WheelOdometry::pose() const { return Odometry{position_.x(), position_.y(), theta_}; }

void WheelOdometry::set_pose(const Odometry& o) {
  position_ = Eigen::Vector2d(o.x_m, o.y_m);
  theta_ = o.theta_rad;
}

// The bus first (nothing reaches a drive on a bus that is off), then a lost drive, then faults.
DriveHealth combine_health(BusState bus, DriveFault left, DriveFault right) {
  if (bus == BusState::off) return DriveHealth::bus_off;
  if (bus == BusState::passive) return DriveHealth::bus_passive;
  if (left == DriveFault::heartbeat_lost || right == DriveFault::heartbeat_lost) return DriveHealth::silent;
  if (left != DriveFault::none || right != DriveFault::none) return DriveHealth::fault;
  return DriveHealth::ok;
}

namespace {
DriveLinkSettings link_settings(const CanConfig& c, std::uint32_t node) {
  DriveLinkSettings s;
  s.node = static_cast<std::uint8_t>(node);
  s.heartbeat_ms = static_cast<std::uint16_t>(c.heartbeat_ms);
  s.heartbeat_timeout_ms = c.heartbeat_timeout_ms;
  s.sdo_timeout_ms = c.sdo_timeout_ms;
  s.fault_reset_ms = c.fault_reset_ms;
  s.host_node = static_cast<std::uint8_t>(c.host_node);
  s.watchdog_ms = static_cast<std::uint16_t>(c.drive_watchdog_ms);
  return s;
}
}  // namespace

CanDrive::CanDrive(FrameTransport& bus, const CanConfig& cfg, std::uint32_t wheel_base_mm)
    : bus_(bus),
      cfg_(cfg),
      left_(link_settings(cfg, cfg.left_node)),
      right_(link_settings(cfg, cfg.right_node)),
      odo_(cfg.counts_per_rev, cfg.wheel_diameter_mm, wheel_base_mm) {}

void CanDrive::start(std::int64_t now_us) {
  now_us_ = now_us;
  left_.start(now_us);
  right_.start(now_us);
  have_ref_ = false;
}

bool CanDrive::on_frame(const can_frame& f, std::int64_t now_us) {
  return left_.on_frame(f, now_us) || right_.on_frame(f, now_us);
}

void CanDrive::send_commands() {
  FrameBatch out;
  const bool on = servo_ && health_ == DriveHealth::ok;
  const std::int32_t l = odo_.counts_per_s(cfg_.left_invert ? -left_cm_s_ : left_cm_s_);
  const std::int32_t r = odo_.counts_per_s(cfg_.right_invert ? -right_cm_s_ : right_cm_s_);
  left_.poll(now_us_, on, on ? l : 0, out);
  right_.poll(now_us_, on, on ? r : 0, out);
  for (std::size_t i = 0; i < out.count; ++i) bus_.send(out.frames[i]);
  bus_.flush();  // a stop goes out now, not at the end of the backend's activation
}

// Off also zeroes the wheels, as the HAL asks.
void CanDrive::set_servo(bool on) {
  servo_ = on;
  if (!on) left_cm_s_ = right_cm_s_ = 0;
  send_commands();
}

// Ignored while the servo is off (HAL contract).
void CanDrive::command_wheels(std::int32_t left_cm_s, std::int32_t right_cm_s) {
  if (!servo_) return;
  left_cm_s_ = left_cm_s;
  right_cm_s_ = right_cm_s;
  send_commands();
}

// What reaches the motors: the set-points only while both drives are operation enabled.
void CanDrive::commanded(std::int32_t& left_cm_s, std::int32_t& right_cm_s) const {
  const bool on = servo_ && health_ == DriveHealth::ok && left_.enabled() && right_.enabled();
  left_cm_s = on ? left_cm_s_ : 0;
  right_cm_s = on ? right_cm_s_ : 0;
}

// A wheel's position is folded in once both have a new one; a drive that restarted (its
// counter may have jumped) gives a new reference instead of a step.
void CanDrive::update_odometry() {
  const DriveLinkStatus& l = left_.status();
  const DriveLinkStatus& r = right_.status();
  if (!l.position_valid || !r.position_valid) return;
  if (l.positions == seen_left_ || r.positions == seen_right_) return;
  seen_left_ = l.positions;
  seen_right_ = r.positions;
  if (!have_ref_ || l.restarts != restarts_left_ || r.restarts != restarts_right_) {
    have_ref_ = true;
    restarts_left_ = l.restarts;
    restarts_right_ = r.restarts;
    ref_left_ = l.position;
    ref_right_ = r.position;
    return;
  }
  // Modular difference: the 32-bit counters may wrap.
  const auto dl = static_cast<std::int32_t>(static_cast<std::uint32_t>(l.position) - static_cast<std::uint32_t>(ref_left_));
  const auto dr = static_cast<std::int32_t>(static_cast<std::uint32_t>(r.position) - static_cast<std::uint32_t>(ref_right_));
  ref_left_ = l.position;
  ref_right_ = r.position;
  const double ml = odo_.metres(cfg_.left_invert ? -static_cast<std::int64_t>(dl) : dl);
  const double mr = odo_.metres(cfg_.right_invert ? -static_cast<std::int64_t>(dr) : dr);
  odo_.advance(ml, mr);
}

void CanDrive::poll(std::int64_t now_us) {
  now_us_ = now_us;
  left_fault_ = left_.fault(now_us);
  right_fault_ = right_.fault(now_us);
  health_ = combine_health(bus_.bus_state(), left_fault_, right_fault_);
  update_odometry();
  send_commands();
}

}  // namespace robuter::hal::can
