// SPDX-License-Identifier: GPL-3.0-or-later
// What the command link checks commands against and reports with: its own sections, and the keys of
// its neighbours' sections it needs, handed over by the firmware's composition (link_settings()).
#pragma once

#include <cstdint>

#include "modules/emergency/emergency_params.hpp"
#include "modules/localise/localise_params.hpp"
#include "modules/planner/planner_params.hpp"
#include "modules/serial/serial_params.hpp"
#include "modules/topics.hpp"
#include "robot/robot_model.hpp"
#include "robot/robot_params.hpp"

namespace robuter {

// Each default is its owner's (a default-made LinkSettings is the default configuration's).
struct LinkSettings {
  PermissionsConfig permissions;  // [permissions]: AY's pass-through, AX
  bool stop_when_clients_leave = LinksConfig{}.stop_when_clients_leave;  // [links]: stop when a pty's last client leaves
  std::uint32_t max_speed_cm_s = RobotConfig{}.max_speed_cm_s;  // robot: the fastest wheel speed AM accepts, cm/s
  robot::RobotModel model = robot::kRobuter;  // the body's reach, for the map window's margin (XG, XQ)
  PlannerModuleConfig planner;                // [planner]: the map window XG and XQ are checked against
  bool report_corrected = LocaliseConfig{}.report_corrected;        // localise: BO, BV and XS in the map frame
  std::uint32_t comm_limit_ticks = EmergencyConfig{}.comm_limit_ticks;  // emergency: XE's link-silence limit, ticks
  UltrasonicSettings initial_us;  // [sonar] and emergency.auto_toggle: the ring's settings at start
};

}  // namespace robuter
