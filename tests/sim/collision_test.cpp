// SPDX-License-Identifier: GPL-3.0-or-later
// Contact between the Robuter's rectangle and the world: bumper, stop at the contact pose, no
// tunnelling through thin walls at any step size, doors that fit and gaps that do not.
#include <gtest/gtest.h>

#include <cmath>

#include "hal/sim/robot.hpp"
#include "hal/sim/world_io.hpp"
#include "tests/sim/sim_test_util.hpp"

namespace robuter::sim {
namespace {

// Instant speed changes: the worst case for contact.
RobotParams quick() {
  RobotParams p;
  p.limits.max_accel = 0.0;  // instant speed changes: the worst case for contact
  p.limits.max_decel = 0.0;
  return p;
}

// Driving into a wall 2 m ahead: stops with the front face at the wall, bumper pressed.
TEST(Collision, BumperAndStopAtContactPose) {
  const World world = test::make_world({test::rect(3.0, -2.0, 3.2, 2.0)});
  Robot robot(world, quick(), {0.0, 0.0, 0.0});
  EXPECT_FALSE(robot.bumper());
  robot.command({0.3, 0.3});
  for (int i = 0; i < 1000 && !robot.blocked(); ++i) robot.step(0.01);
  ASSERT_TRUE(robot.blocked());
  EXPECT_TRUE(robot.bumper());
  const double front = robot.pose().x + robot.params().geometry.axle_to_front;
  EXPECT_LE(front, 3.0);
  EXPECT_GT(front, 3.0 - 1e-4);
  EXPECT_EQ(robot.wheel_speeds().left, 0.0);
  // Still commanded forward: stays put, bumper still pressed.
  const double x = robot.pose().x;
  for (int i = 0; i < 50; ++i) robot.step(0.01);
  EXPECT_EQ(robot.pose().x, x);
  EXPECT_TRUE(robot.bumper());
  // Backing away releases the bumper.
  robot.command({-0.2, -0.2});
  for (int i = 0; i < 10; ++i) robot.step(0.01);
  EXPECT_FALSE(robot.bumper());
  EXPECT_FALSE(robot.blocked());
  EXPECT_LT(robot.pose().x, x);
}

// 1 m/s towards a zero-thickness wall (a two-vertex obstacle) and a 1 cm one, with steps from
// 10 ms to a whole second: the robot never ends beyond the wall.
TEST(Collision, NoTunnellingAtOneMetrePerSecond) {
  for (const bool line_wall : {true, false}) {
    World world;
    if (line_wall) {
      world.add_obstacle({"line", {{2.0, -3.0}, {2.0, 3.0}}, 0});
    } else {
      world.add_obstacle({"thin", test::rect(2.0, -3.0, 2.01, 3.0), 0});
    }
    world.finalize();
    for (const double dt : {0.01, 0.02, 0.05, 0.1, 0.25, 1.0}) {
      SCOPED_TRACE("dt " + std::to_string(dt) + (line_wall ? " line" : " thin"));
      Robot robot(world, quick(), {0.0, 0.0, 0.0});
      robot.command({1.0, 1.0});
      for (double t = 0.0; t < 5.0; t += dt) robot.step(dt);
      EXPECT_TRUE(robot.bumper());
      EXPECT_NEAR(robot.pose().x + 0.695, 2.0, 1e-4);
    }
  }
}

// Spinning in place next to a wall: a corner touches it and the rotation stops there.
TEST(Collision, RotationStopsAtCornerContact) {
  // Body corners are 0.778 m from the axle; a wall 0.5 m to the left is within the swing.
  const World world = test::make_world({test::rect(-3.0, 0.5, 3.0, 0.7)});
  Robot robot(world, quick(), {0.0, 0.0, 0.0});
  robot.command({-0.3, 0.3});
  for (int i = 0; i < 300; ++i) robot.step(0.01);
  EXPECT_TRUE(robot.bumper());
  EXPECT_TRUE(robot.blocked());
  EXPECT_GT(robot.pose().theta, 0.0);
  EXPECT_LT(robot.pose().theta, 1.0);
  Vec2 c[4];
  footprint_corners(robot.params().geometry, robot.pose(), c);
  double top = -1.0;
  for (const auto& p : c) top = std::max(top, p.y());
  EXPECT_LE(top, 0.5);
  EXPECT_GT(top, 0.5 - 1e-4);
}

// A robot placed overlapping a wall cannot move deeper but may leave.
TEST(Collision, StartingInContactMayOnlyLeave) {
  const World world = test::make_world({test::rect(0.69, -1.0, 0.8, 1.0)});
  Robot robot(world, quick(), {0.0, 0.0, 0.0});
  EXPECT_TRUE(robot.bumper());
  robot.command({0.2, 0.2});
  robot.step(0.1);
  EXPECT_EQ(robot.pose().x, 0.0);
  robot.command({-0.2, -0.2});
  robot.step(0.1);
  EXPECT_NEAR(robot.pose().x, -0.02, 1e-12);
}

// Drives straight ahead from the door worlds' start pose for 4 m; true if it got through.
bool drives_through(const std::string& file) {
  auto w = load_world(test::world_path(file));
  EXPECT_TRUE(w.ok()) << (w.ok() ? "" : w.error().describe());
  if (!w.ok()) return false;
  Robot robot(w.value(), RobotParams{}, *w.value().start);
  robot.command({0.3, 0.3});
  for (int i = 0; i < 1100; ++i) robot.step(0.01);  // 3.3 m: 1.5 m beyond the wall
  return !robot.bumper() && robot.pose().y > 5.5;
}

TEST(Collision, NinetyAndHundredCentimetreDoorsFitButSeventyDoesNot) {
  EXPECT_TRUE(drives_through("door90.toml"));
  EXPECT_TRUE(drives_through("door100.toml"));
  EXPECT_FALSE(drives_through("gap70.toml"));
}

TEST(Collision, GapSeventyStopsAtTheWallFace) {
  auto w = load_world(test::world_path("gap70.toml"));
  ASSERT_TRUE(w.ok());
  Robot robot(w.value(), RobotParams{}, *w.value().start);
  robot.command({0.3, 0.3});
  for (int i = 0; i < 2000; ++i) robot.step(0.01);
  EXPECT_TRUE(robot.bumper());
  EXPECT_NEAR(robot.pose().y + 0.695, 3.95, 1e-4);
}

// The grid finds contacts with obstacles far from the origin too.
TEST(Collision, FootprintHitsUsesTheRotatedBody) {
  const World world = test::make_world({test::rect(10.0, 10.0, 10.1, 10.1)});
  GridScratch scratch;
  scratch.prepare(world.segments().size());
  const RobotGeometry g;
  EXPECT_FALSE(footprint_hits(world, g, {9.0, 10.05, 0.0}, 0.0, scratch));     // front 0.305 short
  EXPECT_TRUE(footprint_hits(world, g, {9.4, 10.05, 0.0}, 0.0, scratch));      // front overlaps
  EXPECT_FALSE(footprint_hits(world, g, {10.05, 9.0, kPi / 2}, 0.0, scratch));  // front 0.305 short
  EXPECT_TRUE(footprint_hits(world, g, {10.05, 9.6, kPi / 2}, 0.0, scratch));
  EXPECT_TRUE(footprint_hits(world, g, {9.0, 10.05, 0.0}, 0.31, scratch));      // inflated
}

}  // namespace
}  // namespace robuter::sim
