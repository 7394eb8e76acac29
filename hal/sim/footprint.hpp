// SPDX-License-Identifier: GPL-3.0-or-later
// The Robuter's rectangular footprint and its contact test against the world.
#pragma once

#include "hal/sim/segment_grid.hpp"
#include "hal/sim/world.hpp"
#include "robot/robot_model.hpp"

namespace robuter::sim {

// Body and drive geometry of the simulated robot, by default the robot model's
// (robot/robot_model.hpp). The robot frame has its origin at the midpoint of the wheel axle,
// x forward, y to the left (seen from above).
struct RobotGeometry {
  double length = robot::kRobuter.body.length;                // body length, front face to rear face, m
  double width = robot::kRobuter.body.width;                  // body width, m
  double axle_to_front = robot::kRobuter.body.axle_to_front;  // wheel axle to the front face, m
  double wheel_base = robot::kRobuter.wheels.base;            // distance between the drive wheels, m

  // Distance from the wheel axle to the rear face, m.
  double axle_to_rear() const { return length - axle_to_front; }

  // The body rectangle in the robot frame, grown by `inflate` metres on every side.
  Box body(double inflate = 0.0) const {
    return {Vec2(-axle_to_rear() - inflate, -0.5 * width - inflate),
            Vec2(axle_to_front + inflate, 0.5 * width + inflate)};
  }
};

// The four body corners in the world frame (front-left, front-right, rear-right, rear-left).
void footprint_corners(const RobotGeometry& g, const Pose& pose, Vec2 out[4]);

// Whether the body at `pose`, grown by `inflate` metres, touches any obstacle edge. Edges, not
// interiors, are tested: a robot can only get inside an obstacle by crossing an edge, and the
// loaders refuse start poses inside obstacles.
bool footprint_hits(const World& world, const RobotGeometry& g, const Pose& pose, double inflate,
                    GridScratch& scratch);

}  // namespace robuter::sim
