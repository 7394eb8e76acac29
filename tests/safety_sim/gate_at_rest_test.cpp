// SPDX-License-Identifier: GPL-3.0-or-later
// The gate alone: no re-enable and no new motion while a tripped robot still brakes (at_rest).
#include <gtest/gtest.h>

#include "modules/emergency/motion_gate.hpp"

namespace robuter::emergency {
namespace {

// A gate with fresh, clear ranges on every sensor and a clock that advances one tick per step.
struct Gate {
  MotionGate gate{MotionGateSettings{}};
  UltrasonicRanges ranges{};
  std::uint64_t tick = 1000;

  Gate() {
    ranges.mm.fill(3000);
  }
  // One activation with `in` (ranges, tick and link filled in).
  GateDecision step(GateInputs in = {}) {
    ++tick;
    for (auto& t : ranges.read_tick) t = tick;
    in.tick = tick;
    in.ranges = &ranges;
    in.last_message_tick = tick;
    return gate.step(in);
  }
  // A request for (l, r).
  GateDecision request(int l, int r, GateInputs in = {}) {
    in.new_request = true;
    in.left = l;
    in.right = r;
    return step(in);
  }
};

TEST(GateAtRest, AnObstacleTripIsNotClearableWhileTheRobotStillBrakes) {
  Gate g;
  GateInputs moving;
  moving.at_rest = false;
  ASSERT_FALSE(g.request(60, 60, moving).stop);
  g.ranges.mm[0] = 400;  // under 600 mm at 60 cm/s
  GateDecision d = g.step(moving);
  ASSERT_TRUE(d.tripped);
  EXPECT_TRUE(d.state.latched);
  EXPECT_FALSE(d.state.clearable) << "braking: the cause is not gone";
  g.ranges.mm[0] = 3000;
  GateInputs xr = moving;
  xr.reenable = true;
  d = g.step(xr);
  EXPECT_TRUE(d.state.latched) << "XR refused while braking";
  EXPECT_EQ(d.state.cause, EmergencyCause::obstacle);
  d = g.step();  // at rest now
  EXPECT_TRUE(d.state.clearable);
  xr.at_rest = true;
  d = g.step(xr);
  EXPECT_FALSE(d.state.latched);
  EXPECT_TRUE(d.cleared);
}

TEST(GateAtRest, WithoutLatchARequestWhileBrakingIsATripNotAGrant) {
  MotionGateSettings s;
  s.latch = false;
  Gate g;
  g.gate = MotionGate(s);
  GateInputs moving;
  moving.at_rest = false;
  g.request(60, 60, moving);
  g.ranges.mm[0] = 400;
  ASSERT_TRUE(g.step(moving).tripped);
  g.ranges.mm[0] = 3000;
  GateDecision d = g.request(30, -30, moving);
  EXPECT_TRUE(d.stop) << "not granted while the robot brakes";
  EXPECT_TRUE(d.tripped);
  EXPECT_EQ(d.state.cause, EmergencyCause::obstacle);
  d = g.step();
  EXPECT_EQ(d.state.cause, EmergencyCause::none) << "at rest: clears by itself";
  EXPECT_EQ(d.left, 0) << "the request made while braking was forgotten";
  EXPECT_FALSE(d.stop);
  EXPECT_EQ(g.request(30, -30).left, 30) << "a request at rest is granted";
}

TEST(GateAtRest, AStopByteAtRestIsClearableAtOnceAndTripsOnce) {
  Gate g;
  GateInputs in;
  in.stop_byte = true;
  GateDecision d = g.step(in);
  EXPECT_TRUE(d.state.latched);
  EXPECT_TRUE(d.state.clearable) << "nothing was moving";
  EXPECT_EQ(d.state.trips, 1u);
  for (int i = 0; i < 20; ++i) d = g.step();
  EXPECT_EQ(d.state.trips, 1u) << "the stop byte trips once";
}

TEST(GateAtRest, AStopByteWhileMovingCountsOneTripWhileBraking) {
  Gate g;
  GateInputs moving;
  moving.at_rest = false;
  g.request(40, 40, moving);
  GateInputs stop = moving;
  stop.stop_byte = true;
  GateDecision d = g.step(stop);
  EXPECT_EQ(d.state.trips, 1u);
  for (int i = 0; i < 20; ++i) d = g.step(moving);
  EXPECT_EQ(d.state.trips, 1u) << "braking is not a new trip";
  EXPECT_FALSE(d.state.clearable);
  d = g.step();
  EXPECT_TRUE(d.state.clearable);
}

}  // namespace
}  // namespace robuter::emergency
