// SPDX-License-Identifier: GPL-3.0-or-later
// The configuration's [sim] tables, kept as parsed for the simulated robot (hal/sitl reads them).
#pragma once

#include <memory>

#include <toml++/toml.h>

namespace robuter {

// [sim.robot], [sim.odometry], [sim.sonar], [[sim.sonar.sensor]], [sim.pan_tilt]: the simulated
// robot's own parameters (docs/SIMULATOR.md), checked by hal/sitl when it builds the robot.
struct SimSection {
  // The whole parsed file, kept: a copy of a toml++ node drops its source positions, and the
  // simulated robot's errors name the line (a value out of range in [sim.sonar] said no line).
  std::shared_ptr<const toml::table> document;
  const toml::table* table = nullptr;  // the [sim] table inside it, never null
};

}  // namespace robuter
