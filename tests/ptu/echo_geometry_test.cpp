// SPDX-License-Identifier: GPL-3.0-or-later
// The pan-tilt's echo geometry from a robot model: one rule for the passage finder and the doors.
#include <gtest/gtest.h>

#include "modules/doors/crossing_settings.hpp"
#include "modules/gate/gate_settings.hpp"
#include "modules/ptu/echo_points.hpp"

namespace robuter::ptu {
namespace {

// A mount unlike the Robuter's: every field of the geometry comes from the model or the keys.
robot::RobotModel moved_mount() {
  robot::RobotModel m = robot::kRobuter;
  m.pan_tilt.pivot_x = 0.120;             // m
  m.pan_tilt.face_offset = 0.065;         // m
  m.pan_tilt.half_angle = 10.0 * robot::kDeg;
  return m;
}

TEST(EchoGeometry, ComesFromTheModelsMountAndTheTwoKeys) {
  const EchoGeometry g = echo_geometry(moved_mount(), 35, 3000);
  EXPECT_DOUBLE_EQ(g.pivot_x_mm, 120.0);
  EXPECT_DOUBLE_EQ(g.face_mm, 65.0);
  EXPECT_NEAR(g.beam_half_deg, 10.0, 1e-12);
  EXPECT_EQ(g.same_echo_mm, 35);
  EXPECT_EQ(g.far_mm, 3000);
  EXPECT_EQ(g.run_window_ticks, EchoGeometry{}.run_window_ticks);
}

TEST(EchoGeometry, TheRobutersIsTheDefault) {
  const EchoGeometry g = echo_geometry(robot::kRobuter, 20, 2400);
  const EchoGeometry d{};
  EXPECT_DOUBLE_EQ(g.pivot_x_mm, d.pivot_x_mm);
  EXPECT_DOUBLE_EQ(g.face_mm, d.face_mm);
  EXPECT_DOUBLE_EQ(g.beam_half_deg, d.beam_half_deg);
  EXPECT_EQ(g.same_echo_mm, d.same_echo_mm);
  EXPECT_EQ(g.far_mm, d.far_mm);
}

// The passage finder and the door crossing take the geometry they are given, as it is.
TEST(EchoGeometry, TheGateAndTheDoorsTakeTheSameOne) {
  const robot::RobotModel m = moved_mount();
  const EchoGeometry g = echo_geometry(m, 35, 3000);
  const gate::GateSettings gs = gate::gate_settings(GateConfig{}, m, g);
  const doors::CrossingSettings ds = doors::crossing_settings(DoorsConfig{}, m, g);
  for (const EchoGeometry* e : {&gs.door.geometry, &ds.echoes}) {
    EXPECT_DOUBLE_EQ(e->pivot_x_mm, 120.0);
    EXPECT_DOUBLE_EQ(e->face_mm, 65.0);
    EXPECT_EQ(e->same_echo_mm, 35);
    EXPECT_EQ(e->far_mm, 3000);
  }
}

}  // namespace
}  // namespace robuter::ptu
