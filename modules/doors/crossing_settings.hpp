// SPDX-License-Identifier: GPL-3.0-or-later
// The [doors] section, the robot model and the pan-tilt's echoes in the door crossing's terms.
#pragma once

#include "modules/doors/crossing.hpp"
#include "modules/doors/doors_params.hpp"
#include "modules/ptu/echo_points.hpp"
#include "robot/robot_model.hpp"

namespace robuter::doors {

CrossingSettings crossing_settings(const DoorsConfig& d, const robot::RobotModel& m, const ptu::EchoGeometry& echoes);

}  // namespace robuter::doors
