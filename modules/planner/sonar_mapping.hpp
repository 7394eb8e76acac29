// SPDX-License-Identifier: GPL-3.0-or-later
// The ring's readings and the robot's body written into the occupancy map (seed 003's counts).
#pragma once

#include "modules/planner/lib/geometry.hpp"
#include "modules/planner/lib/occupancy_map.hpp"
#include "robot/robot_model.hpp"

namespace robuter::planner {

using SensorMount = robot::SonarMount;  // a transducer in the robot frame (m, rad)

// Why: one reading of sensor `mount` with the robot at `robot` (axle midpoint, m, rad) in seed
// 003's counts: the cells before the echo lose a hit, the echo's cell gains one. The echo may
// come from anywhere on the arc of the cone (`half_angle`, rad; 0 = the axis only, as seed 003):
// the hit goes to the arc cell with the most evidence of an obstacle (nearest the axis among
// equals), so an echo from a door's jamb seen at the cone's edge does not close the doorway.
// A reading at or beyond `beam_range` (m), and a "no echo", only clears along the axis up to
// `beam_range`: far echoes are too wide to place, and too far to matter before the next stop.
// `range` in m; `no_echo` true when nothing came back within `range` (the firing's reach: a
// shortened firing clears only that far).
void integrate_reading(plan::OccupancyMap& map, const plan::Pose2& robot, const SensorMount& mount,
                       double range, bool no_echo, double beam_range, double half_angle);

// Why: the pan-tilt's two sonars (seed 002) sweep the whole turn in 5° sectors; each reading is
// one more beam for the map, fired from the transducer face: the face sits the mount's
// face_offset from the pan axis along the beam's `direction` (rad from the robot's heading).
// Marked with integrate_reading like a ring sensor.
SensorMount pan_tilt_mount(const robot::PanTiltMount& mount, double direction);

// Why: the body stands where it stands, so the cells under it are free: this clears echoes
// that the cone's width put under the robot and keeps its own cell plannable.
void mark_body_free(plan::OccupancyMap& map, const plan::Pose2& robot, const robot::Body& body);

}  // namespace robuter::planner
