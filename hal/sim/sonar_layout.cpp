// Default ring and pan-tilt tables. Robot frame: origin at the wheel-axle midpoint, x forward,
// y left; the body spans x in [-0.330, 0.695] m and y in [-0.350, 0.350] m.
#include "hal/sim/sonar_layout.hpp"

#include <cmath>
#include <limits>

namespace robuter::sim {

namespace {
// One row of the table: number, x (m), y (m), direction (deg), node, slot.
struct Row {
  int number;
  double x, y, direction_deg;
  int node, slot;
};

// Front: sensors 2-4 on the front face at the lateral offsets that give the seed's thresholds
// LIMIT12 2476, LIMIT23 1200, LIMIT34 1011 mm; 5 on the front-right corner (865 mm ~ LIMIT45
// 864, which fixes the axle 695 mm behind the front face); 6 on the right side where r =
// LIMIT56 710 mm. The rest are spread evenly; the left half mirrors the right. Front- and rear-
// face sensors fan out with their lateral offset (45° at the corners); side sensors look square.
// Nodes interleave (node n fires n, n+6, n+12, n+18: four sensors 90° apart, little cross-talk).
constexpr Row kRing[kRingSensors] = {
    {1, 0.6950, 0.0000, 0.0, 1, 1},      {2, 0.6950, -0.09954, -12.8, 2, 1},
    {3, 0.6950, -0.22175, -28.5, 3, 1},   {4, 0.6950, -0.27677, -35.6, 4, 1},
    {5, 0.6950, -0.3500, -45.0, 5, 1},   {6, 0.61196, -0.3500, -90.0, 6, 1},
    {7, 0.3765, -0.3500, -90.0, 1, 2},   {8, 0.1410, -0.3500, -90.0, 2, 2},
    {9, -0.0945, -0.3500, -90.0, 3, 2},  {10, -0.3300, -0.3500, -135.0, 4, 2},
    {11, -0.3300, -0.2333, -150.0, 5, 2}, {12, -0.3300, -0.1167, -165.0, 6, 2},
    {13, -0.3300, 0.0000, 180.0, 1, 3},  {14, -0.3300, 0.1167, 165.0, 2, 3},
    {15, -0.3300, 0.2333, 150.0, 3, 3},  {16, -0.3300, 0.3500, 135.0, 4, 3},
    {17, -0.0945, 0.3500, 90.0, 5, 3},   {18, 0.1410, 0.3500, 90.0, 6, 3},
    {19, 0.3765, 0.3500, 90.0, 1, 4},    {20, 0.61196, 0.3500, 90.0, 2, 4},
    {21, 0.6950, 0.3500, 45.0, 3, 4},    {22, 0.6950, 0.27677, 35.6, 4, 4},
    {23, 0.6950, 0.22175, 28.5, 5, 4},    {24, 0.6950, 0.09954, 12.8, 6, 4},
};
}  // namespace

// Expands the constant table into mounts.
RingLayout default_ring_layout() {
  RingLayout out{};
  for (int i = 0; i < kRingSensors; ++i) {
    const Row& r = kRing[i];
    out[i] = {r.number, Vec2(r.x, r.y), deg_to_rad(r.direction_deg), r.node, r.slot};
  }
  return out;
}

// Seed 002: single-shot, T=33 ms, V=300 m/s.
SonarParams default_ring_params() { return SonarParams{}; }

// The seed's a is to the right (-y) and b ahead (+x) of the axle.
double trajectory_radius(const SonarMount& mount) {
  const double a = -mount.position.y(), b = mount.position.x();
  if (a == 0.0) return std::numeric_limits<double>::infinity();
  return (a * a + b * b) / (2.0 * a);
}

// Seed 002 ptu.h/ptu.c: PAN_TIME_OUT 15 ms, SOUND_SPEED 335 m/s, fitted Y = 0.96 X + 43 mm.
SonarParams default_pan_tilt_params() {
  SonarParams p;
  p.timeout = 0.015;
  p.sound_speed = 335.0;
  p.scale = 0.96;
  p.offset = 0.043;
  return p;
}

// Both transducers sit sensor_offset from the pivot along their own beam axes.
std::array<SonarMount, 2> pan_tilt_mounts(const PanTiltMount& mount, double direction) {
  const Vec2 u(std::cos(direction), std::sin(direction));
  return {SonarMount{0, mount.pivot + mount.sensor_offset * u, wrap_angle(direction), 0, 0},
          SonarMount{0, mount.pivot - mount.sensor_offset * u, wrap_angle(direction + kPi), 0,
                     0}};
}

// The same cone tracer as the ring, with the pan-tilt's parameters.
PanTiltReading measure_pan_tilt(SonarModel& model, const Pose& robot, const PanTiltMount& mount,
                                double direction, Rng* rng) {
  const auto m = pan_tilt_mounts(mount, direction);
  return {model.measure(robot, m[0], rng), model.measure(robot, m[1], rng)};
}

}  // namespace robuter::sim
