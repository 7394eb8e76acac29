// SPDX-License-Identifier: GPL-3.0-or-later
// The configuration's [sim] tables, kept as parsed for the simulated robot (hal/sitl reads them).
#pragma once

#include <toml++/toml.h>

namespace robuter {

// [sim.robot], [sim.odometry], [sim.sonar], [[sim.sonar.sensor]], [sim.pan_tilt]: the simulated
// robot's own parameters (docs/SIMULATOR.md), checked by hal/sitl when it builds the robot.
struct SimSection {
  toml::table table;  // the [sim] table, with its source positions for file:line errors
};

}  // namespace robuter
