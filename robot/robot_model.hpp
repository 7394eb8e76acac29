// SPDX-License-Identifier: GPL-3.0-or-later
// The Robuter as every part of the firmware and the simulator sees it: body, wheels, ultrasonic
// ring (sensors, cones, node wiring) and pan-tilt mount — the one place these numbers are stated.
// Plain numbers (no Eigen) so that the configuration's defaults can name them; the geometry on
// top of them (Eigen) is robot/model_geometry.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "robot/ring_wiring.hpp"

namespace robuter::robot {

inline constexpr double kDeg = std::numbers::pi / 180.0;  // radians per degree

// The body: a rectangle in the robot frame (origin at the wheel-axle midpoint, x forward, y left).
struct Body {
  double length = 1.025;         // front face to rear face, m (seed 002 doors.h ROBOT_LENGTH)
  double width = 0.700;          // side to side, m (ROBOT_WIDTH)
  double axle_to_front = 0.695;  // wheel axle to the front face, m (the seed's thresholds
                                 // LIMIT12…LIMIT56; PAN_X_POSITION 725 with the pan axis 30 mm
                                 // behind the axle; docs/ROBOT.md)

  // Wheel axle to the rear face, m.
  constexpr double axle_to_rear() const { return length - axle_to_front; }
  // The rectangle's centre ahead of the wheel axle, m (negative: behind).
  constexpr double center_ahead() const { return axle_to_front - 0.5 * length; }
  // Farthest body point from the axle midpoint, m (the radius swept turning in place).
  double corner_radius() const { return std::hypot(std::max(axle_to_front, axle_to_rear()), 0.5 * width); }
};

// The drive wheels.
struct Wheels {
  double base = 0.600;      // between the two drive wheels (DBW), m (seed 002)
  double max_speed = 1.00;  // largest wheel speed accepted, m/s
  double max_accel = 0.50;  // wheel acceleration limit, m/s²
  double max_decel = 1.00;  // wheel deceleration when told to slow down or stop, m/s² (the drive
                            // brakes at twice its acceleration limit; the simulator likewise)
};

// Where a sonar transducer sits in the robot frame and where it looks.
struct SonarMount {
  double x = 0.0;          // transducer ahead of the axle, m
  double y = 0.0;          // transducer left of the axle midpoint, m
  double direction = 0.0;  // beam axis, rad, counter-clockwise from forward
};

// One ring sensor: its mount and the node slot that fires it.
struct RingSensor {
  SonarMount mount;        // where it sits and looks
  int node = 0;            // node that fires it, 0..5
  int slot = 0;            // its place on that node, 0..3 (bit of the node's firing mask)
};

// The ultrasonic ring: entry s − 1 is sensor s.
struct Ring {
  std::array<RingSensor, kRingSensors> sensors{};  // sensors 1..24
  double half_angle = 12.5 * kDeg;                 // beam cone half-angle, rad (Polaroid 600-series)
  double blanking = 0.15;                          // nearer echoes are lost while the transducer rings, m

  constexpr const RingSensor& sensor(int s) const { return sensors[static_cast<std::size_t>(s - 1)]; }
};

// The pan-tilt unit: two transducers back to back on the pan axis.
struct PanTiltMount {
  double pivot_x = -0.030;     // pan axis ahead of the wheel axle, m, on the centre line (seed:
                               // 725 mm from the front face, 350 mm from the left side)
  double face_offset = 0.050;  // pan axis to each transducer face, m (seed BOX_WIDTH 100 mm / 2)
  double half_angle = 12.5 * kDeg;  // beam cone half-angle, rad
};

// The whole robot.
struct RobotModel {
  Body body;              // the rectangle the safety rules, planner and doors protect
  Wheels wheels;          // differential drive
  Ring ring;              // the 24-sensor ring
  PanTiltMount pan_tilt;  // the pan-tilt's sonars
};

namespace detail {
// One row of the ring table: x, y (m), direction (degrees).
struct MountRow {
  double x, y, direction_deg;
};

// Sensor 1 looks forward and numbers run clockwise seen from above (7 right, 13 rear, 19 left).
// Front face: sensors 2-4 at the lateral offsets where the seed's thresholds hold (LIMIT12 2476,
// LIMIT23 1200, LIMIT34 1011 mm); 5 on the front-right corner (865 mm ≈ LIMIT45 864, which fixes
// the axle 695 mm behind the front face); 6 on the right side where r = LIMIT56 710 mm. The rest
// are spread evenly; the left half mirrors the right. Front- and rear-face sensors fan out with
// their lateral offset (45° at the corners); side sensors look square. docs/ROBOT.md.
inline constexpr MountRow kRingRows[kRingSensors] = {
    {0.6950, 0.0000, 0.0},       {0.6950, -0.09954, -12.8},  {0.6950, -0.22175, -28.5},
    {0.6950, -0.27677, -35.6},   {0.6950, -0.3500, -45.0},   {0.61196, -0.3500, -90.0},
    {0.3765, -0.3500, -90.0},    {0.1410, -0.3500, -90.0},   {-0.0945, -0.3500, -90.0},
    {-0.3300, -0.3500, -135.0},  {-0.3300, -0.2333, -150.0}, {-0.3300, -0.1167, -165.0},
    {-0.3300, 0.0000, 180.0},    {-0.3300, 0.1167, 165.0},   {-0.3300, 0.2333, 150.0},
    {-0.3300, 0.3500, 135.0},    {-0.0945, 0.3500, 90.0},    {0.1410, 0.3500, 90.0},
    {0.3765, 0.3500, 90.0},      {0.61196, 0.3500, 90.0},    {0.6950, 0.3500, 45.0},
    {0.6950, 0.27677, 35.6},     {0.6950, 0.22175, 28.5},    {0.6950, 0.09954, 12.8},
};

constexpr Ring robuter_ring() {
  Ring r;
  for (int s = 1; s <= kRingSensors; ++s) {
    const MountRow& m = kRingRows[s - 1];
    r.sensors[static_cast<std::size_t>(s - 1)] = {{m.x, m.y, m.direction_deg * kDeg}, wired_node(s), wired_slot(s)};
  }
  return r;
}
}  // namespace detail

// The Robuter as built (seed 002): the defaults of every user.
inline constexpr RobotModel kRobuter{Body{}, Wheels{}, detail::robuter_ring(), PanTiltMount{}};

// Every sensor sits on the body's outline (the table and the body agree).
static_assert([] {
  for (const RingSensor& r : kRobuter.ring.sensors) {
    const SonarMount& s = r.mount;
    const Body& b = kRobuter.body;
    const double e = 1e-9, front = b.axle_to_front, rear = -b.axle_to_rear(), side = 0.5 * b.width;
    const auto near = [e](double a, double c) { return a - c < e && c - a < e; };
    const bool on_x = near(s.x, front) || near(s.x, rear);
    const bool on_y = near(s.y, side) || near(s.y, -side);
    const bool inside = s.x < front + e && s.x > rear - e && s.y < side + e && s.y > -side - e;
    if (!inside || !(on_x || on_y)) return false;
  }
  return true;
}());

// Whole millimetres of a length in metres (configuration defaults are stated in mm).
constexpr std::int32_t mm(double metres) {
  return static_cast<std::int32_t>(metres >= 0.0 ? metres * 1000.0 + 0.5 : metres * 1000.0 - 0.5);
}
constexpr std::uint32_t mm_u(double metres) { return static_cast<std::uint32_t>(mm(metres)); }
// Hundredths of a degree of an angle in radians.
constexpr std::int32_t centideg(double rad) {
  const double c = rad / kDeg * 100.0;
  return static_cast<std::int32_t>(c >= 0.0 ? c + 0.5 : c - 0.5);
}

}  // namespace robuter::robot
