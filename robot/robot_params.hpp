// SPDX-License-Identifier: GPL-3.0-or-later
// The robot's parameters ([robot]): the body and wheels of robot/robot_model.hpp in the configuration's units.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/param.hpp"
#include "robot/robot_model.hpp"

namespace robuter {

// The robot the firmware believes it drives: the body and wheels of robot/robot_model.hpp, in
// the configuration's units (robot_model() turns the whole configuration into the model).
struct RobotConfig {
  std::uint32_t length_mm = robot::mm_u(robot::kRobuter.body.length);         // rectangle length along x, mm
  std::uint32_t width_mm = robot::mm_u(robot::kRobuter.body.width);           // rectangle width, mm
  std::uint32_t axle_to_front_mm = robot::mm_u(robot::kRobuter.body.axle_to_front);  // wheel axle to the front face, mm
  std::uint32_t wheel_base_mm = robot::mm_u(robot::kRobuter.wheels.base);     // distance between the drive wheels (DBW), mm
  std::uint32_t max_speed_cm_s = robot::mm_u(robot::kRobuter.wheels.max_speed) / 10;  // largest wheel speed accepted, cm/s
  std::uint32_t max_accel_cm_s2 = robot::mm_u(robot::kRobuter.wheels.max_accel) / 10; // wheel acceleration limit, cm/s²
  std::uint32_t max_decel_cm_s2 = robot::mm_u(robot::kRobuter.wheels.max_decel) / 10; // braking deceleration, cm/s²
};

// [robot]: each key, its unit, range and doc (the default is the field's initialiser).
std::span<const param::Param<RobotConfig>> robot_params();

}  // namespace robuter
