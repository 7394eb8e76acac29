// Where the 24 ring sonars sit on the body and where they look (the firmware's own table).
#pragma once

#include <array>

namespace robuter::planner {

inline constexpr int kRingSensors = 24;  // sensors on the ring, numbered 1..24

// One ring sensor in the robot frame (origin at the wheel-axle midpoint, x forward, y left).
struct SensorMount {
  double x = 0.0;          // m, ahead of the axle
  double y = 0.0;          // m, to the left of the axle midpoint
  double direction = 0.0;  // rad, beam axis, counter-clockwise from the robot's heading
};

// Entry i is sensor i + 1.
using RingGeometry = std::array<SensorMount, kRingSensors>;

// Why: the planner marks each reading along its sensor's beam; the firmware must not depend on
// the simulator, so the mounting table (docs/SIMULATOR.md, "The ring") is repeated here as the
// default: sensor 1 looks forward, numbers run clockwise seen from above (7 right, 13 rear,
// 19 left).
const RingGeometry& default_ring_geometry();

}  // namespace robuter::planner
