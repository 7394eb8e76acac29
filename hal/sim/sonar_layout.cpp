// SPDX-License-Identifier: GPL-3.0-or-later
// The simulator's view of the ring and pan-tilt mounts (robot frame: origin at the wheel-axle
// midpoint, x forward, y left), and the pan-tilt pair's firing.
#include "hal/sim/sonar_layout.hpp"

#include "robot/model_geometry.hpp"

#include <cmath>
#include <limits>

namespace robuter::sim {

// The robot model's table as simulator mounts.
RingLayout default_ring_layout() {
  RingLayout out{};
  for (int s = 1; s <= kRingSensors; ++s) {
    const robot::SonarMount& m = robot::kRobuter.ring.sensor(s).mount;
    out[static_cast<std::size_t>(s - 1)] = {s, robot::position(m), m.direction};
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

// Seed 002 ptu.h: PAN_TIME_OUT 15 ms, SOUND_SPEED 335 m/s; its text's fit Y = 0.96 X + 43 mm (its
// ptu.c corrects with 46, as the firmware does: docs/DOORS.md PT-2).
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
  return {SonarMount{0, mount.pivot + mount.sensor_offset * u, wrap_angle(direction)},
          SonarMount{0, mount.pivot - mount.sensor_offset * u, wrap_angle(direction + kPi)}};
}

// The same cone tracer as the ring, with the pan-tilt's parameters.
PanTiltReading measure_pan_tilt(SonarModel& model, const Pose& robot, const PanTiltMount& mount,
                                double direction, Rng* rng) {
  const auto m = pan_tilt_mounts(mount, direction);
  return {model.measure(robot, m[0], rng), model.measure(robot, m[1], rng)};
}

}  // namespace robuter::sim
