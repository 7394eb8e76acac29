// SPDX-License-Identifier: GPL-3.0-or-later
// The go-to-posture controller on an ideal differential drive, and the posture unit conversions.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "modules/executor/go_to.hpp"
#include "modules/executor/posture_units.hpp"
#include "robot/wheel_speed.hpp"

namespace robuter::executor {
namespace {

// Runs the controller every 100 ms on an ideal robot (wheel speeds reached at once) until done.
struct Plant {
  double x = 0, y = 0, th = 0;  // m, m, rad
  PostureUnits posture() const { return to_posture(hal::Odometry{x, y, th}); }
  void move(WheelSpeeds w, double dt) {
    const double vl = w.left / 100.0, vr = w.right / 100.0;
    const double v = (vl + vr) / 2, om = (vr - vl) / 0.6;
    const double mid = th + om * dt / 2;
    x += v * std::cos(mid) * dt;
    y += v * std::sin(mid) * dt;
    th = std::remainder(th + om * dt, 2 * std::numbers::pi);
  }
};

int drive_to(GoToController& c, Plant& p, PostureUnits target, int max_steps = 5000) {
  c.start(target);
  for (int i = 0; i < max_steps; ++i) {
    const WheelSpeeds w = c.step(p.posture());
    if (!c.active()) return i;
    // 10 sub-steps of 10 ms: the executor's period.
    for (int k = 0; k < 10; ++k) p.move(w, 0.01);
  }
  return -1;
}

struct Target {
  std::int32_t x, y, theta;
};

class GoToTargets : public testing::TestWithParam<Target> {};

TEST_P(GoToTargets, EndsWithinTwoCentimetresAndTwoDegrees) {
  const Target t = GetParam();
  GoToController c;
  Plant p;
  const int steps = drive_to(c, p, {t.x, t.y, t.theta});
  ASSERT_GE(steps, 0) << "did not finish";
  const PostureUnits end = p.posture();
  EXPECT_LE(std::hypot(end.x - t.x, end.y - t.y), 200.0);
  EXPECT_LE(std::abs(wrap_centideg(static_cast<std::int64_t>(end.theta) - t.theta)), 200);
  EXPECT_EQ(c.phase(), GoToPhase::done);
  const WheelSpeeds after = c.step(end);
  EXPECT_EQ(after.left, 0);
  EXPECT_EQ(after.right, 0);
}

INSTANTIATE_TEST_SUITE_P(Targets, GoToTargets,
                         testing::Values(Target{10000, 0, 0}, Target{0, 10000, 9000}, Target{-5000, -5000, 18000},
                                         Target{-10000, 2000, -9000}, Target{300, 0, 0}, Target{0, 0, 9000},
                                         Target{0, 0, -17999}, Target{150, 0, 4500}, Target{20000, -15000, 13500}));

TEST(GoTo, SpeedsStayWithinTheLimits) {
  GoToController c;
  Plant p;
  c.start({30000, 10000, 0});
  for (int i = 0; i < 3000 && c.active(); ++i) {
    const WheelSpeeds w = c.step(p.posture());
    ASSERT_LE(std::abs(w.left), 20);
    ASSERT_LE(std::abs(w.right), 20);
    for (int k = 0; k < 10; ++k) p.move(w, 0.01);
  }
  EXPECT_FALSE(c.active());
}

TEST(GoTo, TurnsFirstThenDrives) {
  GoToController c;
  c.start({0, 10000, 0});  // 1 m to the left
  const WheelSpeeds w = c.step({0, 0, 0});
  EXPECT_EQ(c.phase(), GoToPhase::turn_to_target);
  EXPECT_EQ(w.left, -w.right) << "on the spot";
  EXPECT_GT(w.right, 0) << "counter-clockwise towards +y";
}

TEST(GoTo, CancelStops) {
  GoToController c;
  c.start({10000, 0, 0});
  EXPECT_TRUE(c.active());
  c.cancel();
  EXPECT_FALSE(c.active());
  EXPECT_EQ(c.phase(), GoToPhase::idle);
}

TEST(PostureUnits, ThetaRangeIsMinusHalfTurnExclusiveToHalfTurn) {
  EXPECT_EQ(wrap_centideg(18000), 18000);
  EXPECT_EQ(wrap_centideg(-18000), 18000);
  EXPECT_EQ(wrap_centideg(-17999), -17999);
  EXPECT_EQ(wrap_centideg(36000), 0);
  EXPECT_EQ(wrap_centideg(27000), -9000);
  EXPECT_EQ(wrap_centideg(-27000), 9000);
  EXPECT_EQ(radians_to_centideg(std::numbers::pi), 18000);
  EXPECT_EQ(radians_to_centideg(-std::numbers::pi), 18000);
  EXPECT_EQ(radians_to_centideg(std::numbers::pi / 2), 9000);
}

TEST(PostureUnits, MetresAndTenthsOfMillimetres) {
  const PostureUnits p = to_posture({1.2345, -0.5, 0.0});
  EXPECT_EQ(p.x, 12345);
  EXPECT_EQ(p.y, -5000);
  const hal::Odometry o = to_odometry({12345, -5000, 9000});
  EXPECT_DOUBLE_EQ(o.x_m, 1.2345);
  EXPECT_DOUBLE_EQ(o.y_m, -0.5);
  EXPECT_NEAR(o.theta_rad, std::numbers::pi / 2, 1e-12);
  EXPECT_EQ(metres_to_tenth_mm(1e12), 2147483647);
  EXPECT_EQ(metres_to_tenth_mm(std::nan("")), 0);
}

// The one rounding of a controller's wheel speed (go-to and the planner's path follower).
TEST(WheelCommand, RoundsToWholeCmPerSecondWithinTheLimitsAndKeepsTheSign) {
  EXPECT_EQ(robot::wheel_command(12.4, 2, 30), 12);
  EXPECT_EQ(robot::wheel_command(-12.6, 2, 30), -13);
  EXPECT_EQ(robot::wheel_command(0.3, 2, 30), 2);    // too little to move the wheel: lo
  EXPECT_EQ(robot::wheel_command(-0.3, 2, 30), -2);
  EXPECT_EQ(robot::wheel_command(80.0, 2, 30), 30);  // at most hi
  EXPECT_EQ(robot::wheel_command(-80.0, 2, 30), -30);
}

}  // namespace
}  // namespace robuter::executor
