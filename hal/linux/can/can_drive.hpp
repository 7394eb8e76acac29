// SPDX-License-Identifier: GPL-3.0-or-later
// hal::Drive on two CiA 402 drives on CAN: servo and wheel speeds as RPDO1s, odometry from encoder counts (Eigen).
#pragma once

#include <Eigen/Core>

#include <cstdint>

#include "hal/api/drive.hpp"
#include "hal/linux/can/drive_link.hpp"
#include "hal/linux/can/frame_transport.hpp"
#include "kernel/config.hpp"

namespace robuter::hal::can {

// Counts ↔ wheel travel ↔ robot motion, for a differential drive. Pure.
class WheelOdometry {
 public:
  // `counts_per_rev` increments per wheel turn, wheel diameter and axle length in mm.
  WheelOdometry(std::uint32_t counts_per_rev, std::uint32_t wheel_diameter_mm, std::uint32_t wheel_base_mm);
  // Wheel speed cm/s → target velocity, increments/s (rounded, saturated to int32).
  std::int32_t counts_per_s(std::int32_t cm_s) const;
  // Increments → wheel travel, m.
  double metres(std::int64_t counts) const { return static_cast<double>(counts) * m_per_count_; }
  // Moves the pose by the wheels' travels (m) along an arc (midpoint heading).
  void advance(double left_m, double right_m);
  Odometry pose() const;
  void set_pose(const Odometry& o);

 private:
  double m_per_count_;            // wheel travel per increment, m
  double counts_per_cm_;          // increments per cm of travel
  double base_m_;                 // distance between the wheels, m
  Eigen::Vector2d position_{0.0, 0.0};  // m, odometry frame
  double theta_ = 0.0;            // rad, (-π, π]
};

// Why the drive pair is not usable, for health() and the logs.
DriveHealth combine_health(BusState bus, DriveFault left, DriveFault right);

// The two wheel drives. The backend process feeds it frames and polls it every tick; the
// executor's commands go out at once as RPDO1s so a stop reaches the drives in the same tick.
class CanDrive final : public Drive {
 public:
  CanDrive(FrameTransport& bus, const CanConfig& cfg, std::uint32_t wheel_base_mm);

  void set_servo(bool on) override;
  bool servo() const override { return servo_; }
  void command_wheels(std::int32_t left_cm_s, std::int32_t right_cm_s) override;
  void commanded(std::int32_t& left_cm_s, std::int32_t& right_cm_s) const override;
  Odometry odometry() const override { return odo_.pose(); }
  void set_odometry(const Odometry& o) override { odo_.set_pose(o); }
  DriveHealth health() const override { return health_; }

  // Backend: bring-up of both drives from `now_us`.
  void start(std::int64_t now_us);
  // Backend: a frame from the bus; false when neither drive's.
  bool on_frame(const can_frame& f, std::int64_t now_us);
  // Backend: timers, RPDO1s, odometry and health at `now_us`; sends through the transport.
  void poll(std::int64_t now_us);

  const DriveLink& left() const { return left_; }
  const DriveLink& right() const { return right_; }
  DriveFault left_fault() const { return left_fault_; }
  DriveFault right_fault() const { return right_fault_; }

 private:
  // Both drives' RPDO1s now (and whatever bring-up step is due).
  void send_commands();
  // Folds new positions of both wheels into the pose.
  void update_odometry();

  FrameTransport& bus_;
  CanConfig cfg_;
  DriveLink left_;
  DriveLink right_;
  WheelOdometry odo_;
  bool servo_ = false;                 // wanted servo state
  std::int32_t left_cm_s_ = 0;         // wanted wheel speeds, cm/s
  std::int32_t right_cm_s_ = 0;
  std::int64_t now_us_ = 0;            // time of the latest poll, µs
  DriveHealth health_ = DriveHealth::silent;
  DriveFault left_fault_ = DriveFault::heartbeat_lost;
  DriveFault right_fault_ = DriveFault::heartbeat_lost;
  // Odometry reference: the last positions folded in, per wheel.
  std::int32_t ref_left_ = 0, ref_right_ = 0;  // increments
  std::uint32_t seen_left_ = 0, seen_right_ = 0;  // DriveLinkStatus::positions folded
  std::uint32_t restarts_left_ = 0, restarts_right_ = 0;  // bring-ups seen (a restart re-references)
  bool have_ref_ = false;              // both references hold a position
};

}  // namespace robuter::hal::can
