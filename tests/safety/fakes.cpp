// SPDX-License-Identifier: GPL-3.0-or-later
// Fake HALs: the drive's rule checks and odometry, the ring's scripted readings.
#include "tests/safety/fakes.hpp"

#include <cmath>
#include <numbers>

namespace robuter::test {

void FakeDrive::record(const DriveCommand& c) { log_[count_++ % kLog] = c; }

void FakeDrive::violate(const char* what) {
  if (violations_++ == 0) what_ = what;
}

// Servo on is power to the wheels: only when no emergency holds and the command is not a stop.
void FakeDrive::set_servo(bool on) {
  record({tick_ ? *tick_ : 0, true, on, 0, 0});
  if (on && bb_) {
    const EmergencyState& e = bb_->emergency.reader().peek();
    const MotionCommand& c = bb_->motion_command.reader().peek();
    if (e.latched || e.cause != EmergencyCause::none) violate("servo on while an emergency holds");
    if (c.stop) violate("servo on while the command is a stop");
  }
  servo_ = on;
  if (!on) left_ = right_ = 0;
}

// A non-zero speed must be exactly what the emergency module grants, with nothing holding.
void FakeDrive::command_wheels(std::int32_t left, std::int32_t right) {
  record({tick_ ? *tick_ : 0, false, false, left, right});
  if ((left != 0 || right != 0) && bb_) {
    const EmergencyState& e = bb_->emergency.reader().peek();
    const MotionCommand& c = bb_->motion_command.reader().peek();
    if (e.latched || e.held || e.cause != EmergencyCause::none) violate("non-zero speed while an emergency holds");
    if (c.stop || c.left != left || c.right != right) violate("speed the emergency module did not grant");
  }
  if (!servo_) return;  // ignored while the servo is off, as the HAL says
  left_ = left;
  right_ = right;
}

// Exact arc integration is not needed at 10 ms steps: mid-point heading is enough.
void FakeDrive::advance(double dt_s, double wheel_base_m) {
  if (!servo_) return;
  const double vl = left_ / 100.0, vr = right_ / 100.0;
  const double v = (vl + vr) / 2.0, w = (vr - vl) / wheel_base_m;
  const double mid = odo_.theta_rad + w * dt_s / 2.0;
  odo_.x_m += v * std::cos(mid) * dt_s;
  odo_.y_m += v * std::sin(mid) * dt_s;
  odo_.theta_rad = std::remainder(odo_.theta_rad + w * dt_s, 2.0 * std::numbers::pi);
}

// A node that always reports at its time-out (the latest the contract allows).
bool FakeRing::fire(int node, std::uint8_t mask, std::uint32_t timeout_ms) {
  if (refuse_fire || node < 0 || node >= hal::kSonarNodes) return false;
  auto& p = nodes_[static_cast<std::size_t>(node)];
  const Nanos now = clock_.now();
  const std::uint32_t t = timeout_ms > 0 && timeout_ms < timeout_ms_ ? timeout_ms : timeout_ms_;
  p = Pending{true, mask, now + static_cast<Nanos>(t) * kNanosPerMilli, t * sound_ / 2};
  log_[fired_++ % kLog] = Firing{node, mask, now, t};
  return true;
}

bool FakeRing::read(int node, hal::NodeRanges& out) {
  if (node < 0 || node >= hal::kSonarNodes) return false;
  auto& p = nodes_[static_cast<std::size_t>(node)];
  if (!p.pending || never_ready || clock_.now() < p.ready) return false;
  p.pending = false;
  for (int i = 0; i < hal::kSensorsPerNode; ++i) {
    const std::uint16_t mm = world[static_cast<std::size_t>(hal::sensor_number(node, i) - 1)];
    out[static_cast<std::size_t>(i)] = (p.mask & (1u << i)) && mm <= p.reach_mm ? mm : std::uint16_t{0};
  }
  return true;
}

}  // namespace robuter::test
