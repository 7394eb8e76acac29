// SPDX-License-Identifier: GPL-3.0-or-later
// The robot's parameters ([robot]): the body and wheels of robot/robot_model.hpp in the configuration's units: the table (compiled once, not in every includer of the configuration).
#include "robot/robot_params.hpp"

namespace robuter {

std::span<const param::Param<RobotConfig>> robot_params() {
  using P = param::Param<RobotConfig>;
  static constexpr P kRows[] = {
      P::integer("length_mm", &RobotConfig::length_mm, "mm", 100, 10'000, "rectangle length along x, mm"),
      P::integer("width_mm", &RobotConfig::width_mm, "mm", 100, 10'000, "rectangle width, mm"),
      P::integer("axle_to_front_mm", &RobotConfig::axle_to_front_mm, "mm", 1, 10'000, "wheel axle to the front face, mm"),
      P::integer("wheel_base_mm", &RobotConfig::wheel_base_mm, "mm", 100, 10'000, "distance between the drive wheels (DBW), mm"),
      P::integer("max_speed_cm_s", &RobotConfig::max_speed_cm_s, "cm/s", 1, 500, "largest wheel speed accepted, cm/s"),
      P::integer("max_accel_cm_s2", &RobotConfig::max_accel_cm_s2, "cm/s²", 1, 10'000, "wheel acceleration limit, cm/s²"),
      P::integer("max_decel_cm_s2", &RobotConfig::max_decel_cm_s2, "cm/s²", 1, 10'000, "braking deceleration, cm/s²"),
  };
  return kRows;
}

}  // namespace robuter
