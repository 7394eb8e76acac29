// SPDX-License-Identifier: GPL-3.0-or-later
// Kinematics of the simulated Robuter against closed-form unicycle motion.
#include <gtest/gtest.h>

#include <cmath>

#include "hal/sim/robot.hpp"
#include "tests/sim/sim_test_util.hpp"

namespace robuter::sim {
namespace {

// Instant wheel-speed changes, so the motion is exactly the commanded arc.
RobotParams instant() {
  RobotParams p;
  p.limits.max_accel = 0.0;
  p.limits.max_decel = 0.0;
  p.limits.max_wheel_speed = 5.0;
  return p;
}

// Closed-form pose after t seconds at constant v, w from p.
Pose closed_form(const Pose& p, double v, double w, double t) {
  if (w == 0.0) return {p.x + v * t * std::cos(p.theta), p.y + v * t * std::sin(p.theta), p.theta};
  const double r = v / w;
  return {p.x + r * (std::sin(p.theta + w * t) - std::sin(p.theta)),
          p.y - r * (std::cos(p.theta + w * t) - std::cos(p.theta)), wrap_angle(p.theta + w * t)};
}

double position_error(const Pose& a, const Pose& b) { return std::hypot(a.x - b.x, a.y - b.y); }

class ArcTest : public ::testing::TestWithParam<double> {};

// 10 m along circles of several radii (both turning senses), 10 ms steps: under 1 mm.
TEST_P(ArcTest, TenMetresMatchClosedFormWithinOneMillimetre) {
  const World world = test::make_world({});
  const double radius = GetParam();
  const double v = 0.5, b = 0.6;
  const double w = v / radius;
  const Pose start{1.0, -2.0, 0.3};
  Robot robot(world, instant(), start);
  robot.command({v - w * b / 2, v + w * b / 2});
  const double dt = 0.01;
  const int steps = static_cast<int>(std::lround(10.0 / v / dt));
  for (int i = 0; i < steps; ++i) robot.step(dt);
  const Pose expect = closed_form(start, v, w, steps * dt);
  EXPECT_LT(position_error(robot.pose(), expect), 1e-3);
  EXPECT_NEAR(wrap_angle(robot.pose().theta - expect.theta), 0.0, 1e-9);
  EXPECT_NEAR(robot.travelled(), 10.0, 1e-9);
  // Noise-free odometry agrees with the truth.
  EXPECT_LT(position_error(robot.odometry(), robot.pose()), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Radii, ArcTest, ::testing::Values(0.4, 1.0, 2.5, -1.5, 10.0, -40.0));

// Irregular steps integrate the same arc (no step-size dependence).
TEST(Kinematics, IrregularStepsStillExact) {
  const World world = test::make_world({});
  const Pose start{0.0, 0.0, -1.0};
  Robot robot(world, instant(), start);
  robot.command({0.3, 0.5});
  double t = 0.0;
  for (int i = 0; t < 20.0; ++i) {
    const double dt = 0.003 + 0.047 * ((i * 7919) % 13) / 13.0;
    robot.step(dt);
    t += dt;
  }
  const Pose expect = closed_form(start, 0.4, 0.2 / 0.6, t);
  EXPECT_LT(position_error(robot.pose(), expect), 1e-6);
}

TEST(Kinematics, StraightLine) {
  const World world = test::make_world({});
  Robot robot(world, instant(), {0.0, 0.0, 0.0});
  robot.command({1.0, 1.0});
  for (int i = 0; i < 1000; ++i) robot.step(0.01);
  EXPECT_NEAR(robot.pose().x, 10.0, 1e-9);
  EXPECT_EQ(robot.pose().y, 0.0);
  EXPECT_EQ(robot.pose().theta, 0.0);
}

TEST(Kinematics, StraightLineAtAnAngle) {
  const World world = test::make_world({});
  const double a = deg_to_rad(37.0);
  Robot robot(world, instant(), {2.0, 3.0, a});
  robot.command({-0.25, -0.25});  // backwards
  for (int i = 0; i < 4000; ++i) robot.step(0.01);
  EXPECT_NEAR(robot.pose().x, 2.0 - 10.0 * std::cos(a), 1e-9);
  EXPECT_NEAR(robot.pose().y, 3.0 - 10.0 * std::sin(a), 1e-9);
  EXPECT_NEAR(robot.pose().theta, a, 1e-12);
}

TEST(Kinematics, PureRotationStaysInPlace) {
  const World world = test::make_world({});
  Robot robot(world, instant(), {1.0, 1.0, 0.0});
  robot.command({-0.15, 0.15});  // w = 0.3 / 0.6 = 0.5 rad/s, counter-clockwise
  for (int i = 0; i < 300; ++i) robot.step(0.01);
  EXPECT_NEAR(robot.pose().x, 1.0, 1e-12);
  EXPECT_NEAR(robot.pose().y, 1.0, 1e-12);
  EXPECT_NEAR(robot.pose().theta, 1.5, 1e-12);
  for (int i = 0; i < 1000; ++i) robot.step(0.01);  // 6.5 rad: wraps
  EXPECT_NEAR(robot.pose().theta, wrap_angle(6.5), 1e-9);
  EXPECT_EQ(robot.travelled(), 0.0);
}

// From rest at 0.5 m/s²: 0.5 m/s after 1 s, 0.25 m covered.
TEST(Kinematics, AccelerationLimit) {
  const World world = test::make_world({});
  RobotParams p;
  p.limits.max_accel = 0.5;
  p.limits.max_decel = 1.0;
  Robot robot(world, p, {0.0, 0.0, 0.0});
  robot.command({0.8, 0.8});
  for (int i = 0; i < 100; ++i) robot.step(0.01);
  EXPECT_NEAR(robot.wheel_speeds().left, 0.5, 1e-9);
  EXPECT_NEAR(robot.pose().x, 0.25, 1e-9);
  for (int i = 0; i < 100; ++i) robot.step(0.01);  // reaches 0.8 at 1.6 s
  EXPECT_NEAR(robot.wheel_speeds().right, 0.8, 1e-12);
  EXPECT_NEAR(robot.pose().x, 0.5 * 0.5 * 1.6 * 1.6 + 0.8 * 0.4, 1e-9);
  robot.command({0.0, 0.0});  // brakes at 1 m/s²: 0.8 s, 0.32 m
  for (int i = 0; i < 100; ++i) robot.step(0.01);
  EXPECT_EQ(robot.wheel_speeds().left, 0.0);
  EXPECT_NEAR(robot.pose().x, 0.64 + 0.32 + 0.32, 1e-9);
}

// Both wheels reach their targets together, so a curve started from rest stays on its circle.
TEST(Kinematics, RampKeepsCommandedCurvature) {
  const World world = test::make_world({});
  RobotParams p;
  p.limits.max_accel = 0.3;
  Robot robot(world, p, {0.0, 0.0, 0.0});
  const double radius = 1.2, b = 0.6;
  robot.command({0.4 * (radius - b / 2) / radius, 0.4 * (radius + b / 2) / radius});
  for (int i = 0; i < 500; ++i) {
    robot.step(0.01);
    EXPECT_NEAR(std::hypot(robot.pose().x, robot.pose().y - radius), radius, 1e-6);
  }
}

TEST(Kinematics, CommandsInCentimetresPerSecondAndClamped) {
  const World world = test::make_world({});
  RobotParams p;
  p.limits.max_wheel_speed = 0.6;
  Robot robot(world, p, {});
  robot.command_cm_s(50, -80);
  EXPECT_DOUBLE_EQ(robot.commanded().left, 0.5);
  EXPECT_DOUBLE_EQ(robot.commanded().right, -0.6);
}

// Encoder errors: deterministic for a seed, different across seeds, slip unseen by encoders.
TEST(Odometry, SeededNoiseIsRepeatable) {
  const World world = test::make_world({});
  RobotParams p = instant();
  p.odometry.noise = 0.01;
  p.odometry.seed = 42;
  auto run = [&](std::uint64_t seed) {
    p.odometry.seed = seed;
    Robot r(world, p, {});
    r.command({0.5, 0.4});
    for (int i = 0; i < 1000; ++i) r.step(0.01);
    return std::pair{r.pose(), r.odometry()};
  };
  const auto a = run(42), b = run(42), c = run(43);
  EXPECT_EQ(a.second.x, b.second.x);
  EXPECT_EQ(a.second.theta, b.second.theta);
  EXPECT_NE(a.second.x, c.second.x);
  EXPECT_GT(position_error(a.first, a.second), 1e-4);  // odometry drifted from the truth
  EXPECT_EQ(a.first.x, c.first.x);                     // the true motion did not change
}

TEST(Odometry, SlipShortensTrueMotionOnly) {
  const World world = test::make_world({});
  RobotParams p = instant();
  p.odometry.slip_mean = 0.1;
  Robot robot(world, p, {});
  robot.command({1.0, 1.0});
  for (int i = 0; i < 100; ++i) robot.step(0.01);
  EXPECT_NEAR(robot.pose().x, 0.9, 1e-9);
  EXPECT_NEAR(robot.odometry().x, 1.0, 1e-9);
}

TEST(Odometry, ScaleErrorCurvesTheEstimate) {
  const World world = test::make_world({});
  RobotParams p = instant();
  p.odometry.scale_right = 0.01;
  Robot robot(world, p, {});
  robot.command({1.0, 1.0});
  for (int i = 0; i < 500; ++i) robot.step(0.01);
  EXPECT_EQ(robot.pose().theta, 0.0);
  EXPECT_NEAR(robot.odometry().theta, 0.05 / 0.6, 1e-9);
  robot.set_odometry({0.0, 0.0, 0.0});
  EXPECT_EQ(robot.odometry().x, 0.0);
}

}  // namespace
}  // namespace robuter::sim
