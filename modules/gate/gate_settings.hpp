// SPDX-License-Identifier: GPL-3.0-or-later
// The [gate] section, the robot model and the pan-tilt's echoes in the passage finder's terms.
#pragma once

#include "modules/gate/gate_logic.hpp"
#include "modules/gate/gate_params.hpp"
#include "modules/ptu/echo_points.hpp"
#include "robot/robot_model.hpp"

namespace robuter::gate {

GateSettings gate_settings(const GateConfig& g, const robot::RobotModel& m, const ptu::EchoGeometry& echoes);

}  // namespace robuter::gate
