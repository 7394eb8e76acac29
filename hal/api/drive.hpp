// SPDX-License-Identifier: GPL-3.0-or-later
// HAL: the differential drive — servo (brake) power, wheel speed commands, odometry.
#pragma once

#include <cstdint>

#include "kernel/vocabulary.hpp"

namespace robuter::hal {

// Where the drive's odometry says the robot is.
struct Odometry {
  double x_m = 0.0;        // m, odometry frame
  double y_m = 0.0;        // m
  double theta_rad = 0.0;  // rad, in (-π, π]
};

// Health of the drive as the backend sees it (a real drive reports faults and heartbeats), with
// the words the CAN backend's transition logs write.
#define ROBUTER_DRIVE_HEALTHS(X)                                                                       \
  X(ok, "ok")                         /* answering, no fault */                                        \
  X(fault, "fault")                   /* the drive reports a fault */                                  \
  X(silent, "heartbeat lost")         /* the drive stopped answering (heartbeat lost) */               \
  X(bus_passive, "bus error-passive") /* the bus to the drive is error-passive (frames may be lost) */ \
  X(bus_off, "bus-off")               /* the controller is bus-off: nothing reaches the drive */
enum class DriveHealth : std::uint8_t { ROBUTER_DRIVE_HEALTHS(ROBUTER_VOCAB_ENUMERATOR) };
ROBUTER_VOCABULARY(DriveHealth, ROBUTER_DRIVE_HEALTHS, "fault");

// Only modules/executor holds the Drive: it is the one writer of motor commands.
class Drive {
 public:
  virtual ~Drive() = default;
  // Servo (brake released, motors powered) on or off; off also zeroes the wheel speeds.
  virtual void set_servo(bool on) = 0;
  virtual bool servo() const = 0;
  // Wheel speed set-points, cm/s (left, right); ignored while the servo is off.
  virtual void command_wheels(std::int32_t left_cm_s, std::int32_t right_cm_s) = 0;
  // The last set-points the drive accepted, cm/s (what actually reached the motors).
  virtual void commanded(std::int32_t& left_cm_s, std::int32_t& right_cm_s) const = 0;
  virtual Odometry odometry() const = 0;
  virtual void set_odometry(const Odometry& o) = 0;
  virtual DriveHealth health() const = 0;
};

}  // namespace robuter::hal
