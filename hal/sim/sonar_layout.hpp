// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated ring's and pan-tilt's mounts, by default the robot model's (robot/robot_model.hpp,
// docs/ROBOT.md), and the trajectory radius through a sensor.
#pragma once

#include <array>
#include <span>

#include "hal/sim/sonar.hpp"

namespace robuter::sim {

constexpr int kRingSensors = robot::kRingSensors;  // sensors on the ring
constexpr int kRingNodes = robot::kRingNodes;      // nodes that fire them

// Mounting of every ring sensor; entry i is sensor number i + 1.
using RingLayout = std::array<SonarMount, kRingSensors>;

// The robot model's ring as mounts: sensor 1 looks forward and numbers run clockwise seen from
// above (7 right, 13 rear, 19 left).
RingLayout default_ring_layout();

// The ring's default sonar behaviour (33 ms time-out, 300 m/s).
SonarParams default_ring_params();

// The radius of the trajectory through a sensor, r = (a² + b²) / (2a) for a sensor a metres to
// the right of and b metres ahead of the wheel axle (seed 002, emergency module), m; positive
// for sensors on the right, infinite on the centre line.
double trajectory_radius(const SonarMount& mount);

// Where the pan-tilt unit carries its two sonars (the robot model's mount by default).
struct PanTiltMount {
  Vec2 pivot{robot::kRobuter.pan_tilt.pivot_x, 0.0};             // pan axis in the robot frame, m
  double sensor_offset = robot::kRobuter.pan_tilt.face_offset;   // pan axis to each transducer face, m
};

// The pan-tilt sonars' default behaviour: 15 ms time-out at 335 m/s, and the raw-reading error
// the seed measured (measured = 0.96 · real + 43 mm), which the firmware corrects.
SonarParams default_pan_tilt_params();

// One pan-tilt firing: both transducers fire together.
struct PanTiltReading {
  double facing = 0.0;    // range reported by the sensor looking along `direction`, m
  double opposite = 0.0;  // range reported by the sensor looking the other way, m
};

// The two sensors' mounts for a pan `direction` (robot frame, rad, 0 forward, counter-clockwise)
// of the first sensor; the second looks the opposite way.
std::array<SonarMount, 2> pan_tilt_mounts(const PanTiltMount& mount, double direction);

// Fires both pan-tilt sonars with the robot at `robot` and the first sensor looking along
// `direction` in the robot frame. `model` should carry pan-tilt parameters.
PanTiltReading measure_pan_tilt(SonarModel& model, const Pose& robot, const PanTiltMount& mount,
                                double direction, Rng* rng = nullptr);

}  // namespace robuter::sim
