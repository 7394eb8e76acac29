// SPDX-License-Identifier: GPL-3.0-or-later
// A picture of a door crossing: the world, the robot's trail and end pose, and pan-tilt scans
// drawn where their echoes were (each sector from the pose it was fired at).
#pragma once

#include <span>
#include <string>

#include "hal/sim/render.hpp"
#include "hal/sitl/sim_robot.hpp"
#include "kernel/config.hpp"
#include "modules/topics.hpp"

namespace robuter::test {

// One scan to draw and what places it in the world: the odometry posture and the true pose at
// the same tick (odometry exact in the runs drawn, so every sector's firing pose maps the same way).
struct ScanSnapshot {
  PanTiltScan scan;           // the 72 sectors as the PTU module published them
  Posture odometry;           // odometry at the snapshot (0.1 mm, 0.01°)
  sim::Pose truth;            // the simulator's true pose at the snapshot (m, rad)
  std::string label;          // legend text, e.g. "scan at Ad"
};

// Writes `path` (.png, .svg or .pdf): world, trail, robot at its end pose, each snapshot's sectors
// as rays from the transducer face to the echo (a dot) or to the cap (no echo: no dot), one colour
// per snapshot, named in the legend; titled "door crossing, `title`, date". What was laid out, or
// why nothing was written.
sim::Result<picture::Layout> write_crossing_picture(const hal::SimRobot& r, const Config& cfg,
                                                   std::span<const ScanSnapshot> snaps, const std::string& title,
                                                   const std::string& path);

}  // namespace robuter::test
