// SPDX-License-Identifier: GPL-3.0-or-later
// The passage finder's decisions on scans the simulator's sonar model makes (issue #19): it acts
// only on two scans that agree, and a manoeuvre held in place backs off and looks again.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "modules/gate/gate_logic.hpp"
#include "tests/ptu/scan_maker.hpp"

namespace robuter::gate {
namespace {

// The robot's odometry for a world pose (m, degrees), in the firmware's units.
SectorPose odometry(double x, double y, double heading_deg) {
  return SectorPose{static_cast<std::int32_t>(std::lround(x * 1e4)), static_cast<std::int32_t>(std::lround(y * 1e4)),
                    static_cast<std::int32_t>(std::lround(heading_deg * 100.0))};
}

// Drives the logic through `ticks` activations with the robot at `pose` and `scan` as the latest
// scan (its sectors stamped with the activation's tick, so every activation sees a fresh one).
GateOutput run(GateLogic& g, std::uint64_t& tick, int ticks, PanTiltScan& scan, const SectorPose& pose) {
  GateOutput o;
  for (int i = 0; i < ticks; ++i) {
    ++tick;
    scan.read_tick.fill(tick);
    o = g.step(GateInputs{tick, &scan, pose, false});
  }
  return o;
}

class GateLogicTest : public ::testing::Test {
 protected:
  test::ScanMaker maker_{ROBUTER_WORLDS_DIR "/door90.toml"};
  GateLogic gate_{GateSettings{}};
  std::uint64_t tick_ = 0;
};

// One scan is never acted on: a spurious or lost echo moves an edge by half a metre. The second
// scan from the same place agrees, and the manoeuvre begins.
TEST_F(GateLogicTest, OneScanIsNotActedOnTwoThatAgreeAre) {
  ASSERT_TRUE(maker_.ok());
  const double x = 3.25, y = 2.45, h = 96.0;
  PanTiltScan scan = maker_.scan(x, y, h);
  gate_.start(tick_);
  run(gate_, tick_, 21, scan, odometry(x, y, h));  // settle, then the first fresh scan is read
  EXPECT_EQ(gate_.manoeuvres(), 0u);
  ASSERT_TRUE(gate_.last_estimate().ok);
  const GateOutput o = run(gate_, tick_, 1, scan, odometry(x, y, h));
  EXPECT_EQ(o.state, ModeState::moving);
  EXPECT_EQ(gate_.manoeuvres(), 1u);
  EXPECT_EQ(gate_.disagreements(), 0u);
}

// A scan whose passage lies 30 cm from the previous one's (the odometry says the robot did not
// move) is looked at again, not driven to; a third that agrees with it is.
TEST_F(GateLogicTest, AScanThatDisagreesIsLookedAtAgain) {
  ASSERT_TRUE(maker_.ok());
  const double x = 3.25, y = 2.45, h = 96.0;
  PanTiltScan here = maker_.scan(x, y, h);
  PanTiltScan shifted = maker_.scan(x + 0.30, y, h);  // what a wrong estimate looks like from here
  for (auto& p : shifted.pose) p = odometry(x, y, h);
  gate_.start(tick_);
  run(gate_, tick_, 21, here, odometry(x, y, h));
  GateOutput o = run(gate_, tick_, 1, shifted, odometry(x, y, h));
  EXPECT_EQ(gate_.manoeuvres(), 0u);
  EXPECT_EQ(gate_.disagreements(), 1u);
  EXPECT_NE(o.state, ModeState::moving);
  EXPECT_EQ(o.left, 0);
  EXPECT_EQ(o.right, 0);
  o = run(gate_, tick_, 1, shifted, odometry(x, y, h));
  EXPECT_EQ(o.state, ModeState::moving);
  EXPECT_EQ(gate_.manoeuvres(), 1u);
}

// Scans that never agree end the search with no-passage, stopped.
TEST_F(GateLogicTest, ScansThatNeverAgreeEndInNoPassage) {
  ASSERT_TRUE(maker_.ok());
  const double x = 3.25, y = 2.45, h = 96.0;
  PanTiltScan a = maker_.scan(x, y, h), b = maker_.scan(x + 0.30, y, h);
  for (auto& p : b.pose) p = odometry(x, y, h);
  gate_.start(tick_);
  run(gate_, tick_, 20, a, odometry(x, y, h));
  GateOutput o;
  for (int i = 0; i < 20 && gate_.active(); ++i) o = run(gate_, tick_, 1, i % 2 == 0 ? a : b, odometry(x, y, h));
  EXPECT_EQ(o.state, ModeState::failed);
  EXPECT_EQ(o.reason, ModeReason::no_passage);
  EXPECT_EQ(o.left, 0);
  EXPECT_EQ(o.right, 0);
  EXPECT_EQ(gate_.manoeuvres(), 0u);
}

// A manoeuvre in which the robot does not move for stall_ticks — the safety core holds it on
// evidence it cannot clear from where it stands (docs/DOORS.md §2) — backs off straight, then
// stops, settles and scans again.
TEST_F(GateLogicTest, AManoeuvreHeldInPlaceBacksOffAndLooksAgain) {
  ASSERT_TRUE(maker_.ok());
  const double x = 3.25, y = 2.75, h = 96.0;
  PanTiltScan scan = maker_.scan(x, y, h);
  GateSettings s;
  gate_ = GateLogic(s);
  gate_.start(tick_);
  GateOutput o = run(gate_, tick_, 22, scan, odometry(x, y, h));
  ASSERT_EQ(o.state, ModeState::moving);
  o = run(gate_, tick_, static_cast<int>(s.stall_ticks) - 2, scan, odometry(x, y, h));
  EXPECT_FALSE(o.left == -s.speed_cm_s && o.right == -s.speed_cm_s);  // still the manoeuvre's own speeds
  o = run(gate_, tick_, 3, scan, odometry(x, y, h));
  EXPECT_EQ(gate_.back_offs(), 1u);
  EXPECT_EQ(o.left, -s.speed_cm_s);
  EXPECT_EQ(o.right, -s.speed_cm_s);
  // Backing off along the heading: still backing 5 cm short of back_off_mm, stopped at it.
  const double th = h * std::numbers::pi / 180.0;
  auto back = [&](double d) { return odometry(x - d * std::cos(th), y - d * std::sin(th), h); };
  for (int i = 1; i <= 20; ++i) o = run(gate_, tick_, 1, scan, back(0.01 * i));
  EXPECT_EQ(o.left, -s.speed_cm_s);
  o = run(gate_, tick_, 1, scan, back(s.back_off_mm / 1000.0 + 0.001));
  EXPECT_EQ(o.left, 0);
  EXPECT_EQ(o.right, 0);
  EXPECT_EQ(o.state, ModeState::searching);
  // It scans again from there: the next two agreeing scans give the next manoeuvre.
  PanTiltScan from_back = maker_.scan(x - 0.25 * std::cos(th), y - 0.25 * std::sin(th), h);
  o = run(gate_, tick_, 22, from_back, back(0.25));
  EXPECT_EQ(o.state, ModeState::moving);
  EXPECT_EQ(gate_.manoeuvres(), 2u);
}

// Backing off, held again (something behind): it stops backing and looks again from there.
TEST_F(GateLogicTest, ABackOffHeldInPlaceEndsAndLooksAgain) {
  ASSERT_TRUE(maker_.ok());
  const double x = 3.25, y = 2.45, h = 96.0;
  PanTiltScan scan = maker_.scan(x, y, h);
  GateSettings s;
  gate_.start(tick_);
  run(gate_, tick_, 22, scan, odometry(x, y, h));
  GateOutput o = run(gate_, tick_, static_cast<int>(s.stall_ticks) + 1, scan, odometry(x, y, h));
  ASSERT_EQ(o.left, -s.speed_cm_s);
  o = run(gate_, tick_, static_cast<int>(s.stall_ticks) + 1, scan, odometry(x, y, h));
  EXPECT_EQ(o.left, 0);
  EXPECT_EQ(o.right, 0);
  EXPECT_TRUE(gate_.active());
}

}  // namespace
}  // namespace robuter::gate
