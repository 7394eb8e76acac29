// SPDX-License-Identifier: GPL-3.0-or-later
// The request-to-move gate on its own: grant, hold and resume, trips, latch and re-enable,
// old speeds never resuming, inhibits at rest, motion time-out, hold limit, auto-toggle table.
#include <gtest/gtest.h>

#include "modules/emergency/motion_gate.hpp"

namespace robuter::emergency {
namespace {

// A gate driven tick by tick with a world of ranges.
struct GateRig {
  explicit GateRig(MotionGateSettings s = {}) : gate(s) {
    ranges.mm.fill(2000);
  }
  // One step at the next tick with `in` (tick, ranges and link time stamp filled in).
  GateDecision step(GateInputs in = {}) {
    ++tick;
    ranges.read_tick.fill(tick);
    in.tick = tick;
    in.ranges = &ranges;
    in.last_message_tick = last_message;
    last = gate.step(in);
    return last;
  }
  GateDecision request(std::int32_t l, std::int32_t r, GateInputs in = {}) {
    in.new_request = true;
    in.left = l;
    in.right = r;
    last_message = tick + 1;
    return step(in);
  }
  MotionGate gate;
  UltrasonicRanges ranges;
  std::uint64_t tick = 100;
  std::uint64_t last_message = 100;
  GateDecision last;
};

bool granted(const GateDecision& d, std::int32_t l, std::int32_t r) {
  return !d.stop && d.left == l && d.right == r && !d.state.held && !d.state.latched &&
         d.state.cause == EmergencyCause::none;
}
bool zero(const GateDecision& d) { return d.left == 0 && d.right == 0; }

TEST(Gate, GrantsAClearRequestAndReportsItsWatchSet) {
  GateRig g;
  const GateDecision d = g.request(20, 20);
  EXPECT_TRUE(granted(d, 20, 20));
  EXPECT_EQ(d.state.main_sensor, 1);
  EXPECT_EQ(d.state.watch, watch_mask(1));
  EXPECT_EQ(d.state.safety_mm, 220u);
  EXPECT_TRUE(granted(g.step(), 20, 20)) << "a granted request stays granted";
}

TEST(Gate, HoldsOnMissingDataThenResumesTheRememberedSpeeds) {
  GateRig g;
  g.ranges.mm[24 - 1] = 0;  // a watch-dog sensor of sensor 1 has no reading yet
  GateDecision d = g.request(30, 30);
  EXPECT_TRUE(d.state.held);
  EXPECT_EQ(d.state.sensor, 24);
  EXPECT_FALSE(d.stop) << "a hold is not an emergency: the servo stays as it is";
  EXPECT_TRUE(zero(d));
  EXPECT_EQ(d.selection & sensor_bit(24), sensor_bit(24)) << "the held set keeps firing";
  d = g.step();
  EXPECT_TRUE(d.state.held);
  g.ranges.mm[24 - 1] = 1500;  // data arrives
  d = g.step();
  EXPECT_TRUE(granted(d, 30, 30)) << "the seed resumes a held motion";
}

TEST(Gate, AnObstacleTripsStopsAndForgetsTheRequest) {
  GateRig g;
  EXPECT_TRUE(granted(g.request(50, 50), 50, 50));
  g.ranges.mm[2 - 1] = 450;  // within 500 mm at 50 cm/s
  GateDecision d = g.step();
  EXPECT_TRUE(d.stop);
  EXPECT_TRUE(d.tripped);
  EXPECT_EQ(d.state.cause, EmergencyCause::obstacle);
  EXPECT_EQ(d.state.sensor, 2);
  EXPECT_EQ(d.state.safety_mm, 500u);
  EXPECT_TRUE(d.state.latched);
  EXPECT_EQ(d.state.trips, 1u);
}

TEST(Gate, SlowerMeansCloser) {
  GateRig g;
  g.ranges.mm[1 - 1] = 300;
  EXPECT_TRUE(granted(g.request(20, 20), 20, 20)) << "220 mm at 20 cm/s";
  EXPECT_EQ(g.request(40, 40).state.cause, EmergencyCause::obstacle) << "400 mm at 40 cm/s";
}

TEST(Gate, LatchHoldsUntilReenableAndOnlyWhenTheCauseIsGone) {
  GateRig g;
  g.request(20, 20);
  g.ranges.mm[1 - 1] = 100;
  EXPECT_TRUE(g.step().state.latched);
  g.ranges.mm[1 - 1] = 2000;  // the obstacle went away
  GateDecision d = g.step();
  EXPECT_TRUE(d.state.latched) << "a latched emergency does not clear by itself";
  EXPECT_TRUE(d.stop);
  EXPECT_TRUE(d.state.clearable);
  d = g.request(20, 20);
  EXPECT_TRUE(d.stop) << "requests are refused while latched";
  EXPECT_TRUE(d.state.latched);

  GateInputs xr;
  xr.reenable = true;
  d = g.step(xr);
  EXPECT_TRUE(d.cleared);
  EXPECT_FALSE(d.state.latched);
  EXPECT_EQ(d.state.cause, EmergencyCause::none);
  EXPECT_FALSE(d.stop);
  EXPECT_TRUE(zero(d)) << "after a re-enable the robot stays stopped";
  EXPECT_TRUE(zero(g.step()));
  EXPECT_TRUE(granted(g.request(20, 20), 20, 20)) << "a new request moves it";
}

TEST(Gate, ReenableIsRefusedWhileTheBumperIsPressed) {
  GateRig g;
  g.request(20, 20);
  GateInputs in;
  in.bumpers = 1;
  GateDecision d = g.step(in);
  EXPECT_EQ(d.state.cause, EmergencyCause::bumper);
  EXPECT_TRUE(d.state.latched);
  EXPECT_FALSE(d.state.clearable);
  in.reenable = true;
  d = g.step(in);
  EXPECT_TRUE(d.state.latched) << "cause still present";
  EXPECT_FALSE(d.cleared);
  in.reenable = false;
  in.bumpers = 0;
  d = g.step(in);
  EXPECT_TRUE(d.state.latched) << "the refused XR is not remembered";
  EXPECT_TRUE(d.state.clearable);
  in.reenable = true;
  EXPECT_FALSE(g.step(in).state.latched);
}

TEST(Gate, BumperDetectionOffMakesItClearable) {
  GateRig g;
  g.request(20, 20);
  GateInputs in;
  in.bumpers = 1;
  g.step(in);
  g.gate.set_enabled(kDetectUltrasonic | kDetectComm);
  in.reenable = true;
  const GateDecision d = g.step(in);
  EXPECT_FALSE(d.state.latched);
  EXPECT_EQ(d.state.enabled, kDetectUltrasonic | kDetectComm);
  EXPECT_TRUE(granted(g.request(-10, -10, in), -10, -10)) << "with the bumper off it can back away";
}

TEST(Gate, OldSpeedNeverResumesAfterATripWithoutLatch) {
  MotionGateSettings s;
  s.latch = false;
  GateRig g(s);
  g.request(30, 30);
  g.ranges.mm[1 - 1] = 100;
  GateDecision d = g.step();
  EXPECT_TRUE(d.stop);
  EXPECT_FALSE(d.state.latched);
  g.ranges.mm[1 - 1] = 2000;
  for (int i = 0; i < 50; ++i) {
    d = g.step();
    EXPECT_TRUE(zero(d));
    EXPECT_EQ(d.state.cause, EmergencyCause::none) << "without latch the emergency clears by itself";
  }
  EXPECT_TRUE(granted(g.request(30, 30), 30, 30));
}

TEST(Gate, WithoutLatchARequestAwayFromTheObstacleIsGranted) {
  MotionGateSettings s;
  s.latch = false;
  GateRig g(s);
  g.ranges.mm[1 - 1] = 100;
  EXPECT_TRUE(g.request(20, 20).stop);
  EXPECT_TRUE(granted(g.request(-20, -20), -20, -20));
}

TEST(Gate, CommunicationLossAfterTheLimit) {
  MotionGateSettings s;
  s.comm_limit_ticks = 50;
  GateRig g(s);
  g.request(10, 10);
  g.last_message = g.tick;
  for (int i = 0; i < 50; ++i) ASSERT_FALSE(g.step().stop) << i;
  const GateDecision d = g.step();  // 51 ticks of silence
  EXPECT_TRUE(d.stop);
  EXPECT_EQ(d.state.cause, EmergencyCause::comm_loss);
  EXPECT_TRUE(d.state.latched);
  EXPECT_FALSE(d.state.clearable);
  g.last_message = g.tick + 1;  // the XR itself is a message
  GateInputs xr;
  xr.reenable = true;
  EXPECT_FALSE(g.step(xr).state.latched);
}

TEST(Gate, CommunicationLossAtRestInhibitsWithoutLatching) {
  MotionGateSettings s;
  s.comm_limit_ticks = 50;
  GateRig g(s);
  for (int i = 0; i < 60; ++i) g.step();
  GateDecision d = g.step();
  EXPECT_EQ(d.state.cause, EmergencyCause::comm_loss);
  EXPECT_TRUE(d.stop) << "servo off while nobody talks";
  EXPECT_FALSE(d.state.latched) << "nothing was interrupted";
  EXPECT_FALSE(d.tripped);
  EXPECT_TRUE(granted(g.request(10, 10), 10, 10)) << "the next message ends it";
}

TEST(Gate, CommunicationDetectionOff) {
  MotionGateSettings s;
  s.comm_limit_ticks = 10;
  s.enabled = kDetectBumper | kDetectUltrasonic;
  GateRig g(s);
  g.request(10, 10);
  for (int i = 0; i < 100; ++i) ASSERT_FALSE(g.step().stop);
}

TEST(Gate, StopByteLatchesEvenAtRest) {
  GateRig g;
  GateInputs in;
  in.stop_byte = true;
  GateDecision d = g.step(in);
  EXPECT_TRUE(d.stop);
  EXPECT_EQ(d.state.cause, EmergencyCause::stop_byte);
  EXPECT_TRUE(d.state.latched);
  EXPECT_TRUE(d.state.clearable);
  GateInputs xr;
  xr.reenable = true;
  EXPECT_FALSE(g.step(xr).state.latched);
}

TEST(Gate, StopByteWhileMoving) {
  GateRig g;
  g.request(40, 40);
  GateInputs in;
  in.stop_byte = true;
  const GateDecision d = g.step(in);
  EXPECT_TRUE(d.stop);
  EXPECT_TRUE(d.tripped);
  EXPECT_EQ(d.state.cause, EmergencyCause::stop_byte);
}

TEST(Gate, BumperWhileMovingAndBumperDetectionOff) {
  GateRig g;
  g.request(10, 10);
  GateInputs in;
  in.bumpers = 2;
  EXPECT_EQ(g.step(in).state.cause, EmergencyCause::bumper);
  GateRig h;
  h.gate.set_enabled(kDetectUltrasonic | kDetectComm);
  h.request(10, 10);
  EXPECT_TRUE(granted(h.step(in), 10, 10));
}

TEST(Gate, DriveFaultTrips) {
  GateRig g;
  g.request(10, 10);
  GateInputs in;
  in.drive_fault = true;
  GateDecision d = g.step(in);
  EXPECT_EQ(d.state.cause, EmergencyCause::drive_fault);
  EXPECT_TRUE(d.state.latched);
  in.reenable = true;
  EXPECT_TRUE(g.step(in).state.latched) << "still faulty";
}

TEST(Gate, UltrasonicDetectionOffIgnoresObstaclesAndMissingData) {
  MotionGateSettings s;
  s.enabled = kDetectBumper | kDetectComm;
  GateRig g(s);
  g.ranges.mm.fill(0);
  g.ranges.mm[1 - 1] = 50;
  EXPECT_TRUE(granted(g.request(20, 20), 20, 20));
}

TEST(Gate, MotionTimeoutStopsAMotionWithoutFreshRequests) {
  MotionGateSettings s;
  s.motion_timeout_ticks = 30;
  GateRig g(s);
  g.request(10, 10);
  for (int i = 0; i < 29; ++i) ASSERT_FALSE(g.step().stop) << i;
  EXPECT_FALSE(g.request(10, 10).stop) << "a fresh request restarts the clock";
  for (int i = 0; i < 30; ++i) ASSERT_FALSE(g.step().stop) << i;
  const GateDecision d = g.step();
  EXPECT_TRUE(d.stop);
  EXPECT_EQ(d.state.cause, EmergencyCause::motion_timeout);
}

TEST(Gate, MotionTimeoutDoesNotApplyAtRest) {
  MotionGateSettings s;
  s.motion_timeout_ticks = 30;
  GateRig g(s);
  g.request(0, 0);
  for (int i = 0; i < 100; ++i) ASSERT_FALSE(g.step().stop);
}

TEST(Gate, AHoldTooLongForgetsTheRequest) {
  MotionGateSettings s;
  s.hold_limit_ticks = 20;
  GateRig g(s);
  g.ranges.mm[1 - 1] = 0;
  g.request(10, 10);
  GateDecision d;
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(g.step().state.held);
  d = g.step();
  EXPECT_TRUE(d.hold_expired);
  EXPECT_FALSE(d.state.held);
  g.ranges.mm[1 - 1] = 2000;
  for (int i = 0; i < 10; ++i) EXPECT_TRUE(zero(g.step())) << "the stale request never resumes";
}

TEST(Gate, AServoRequestStopsTheMotion) {
  GateRig g;
  g.request(10, 10);
  GateInputs in;
  in.servo_request = true;
  const GateDecision d = g.step(in);
  EXPECT_TRUE(zero(d));
  EXPECT_FALSE(d.stop);
  EXPECT_TRUE(zero(g.step()));
}

TEST(Gate, AutoToggleSelectsTheWatchSetOrNothing) {
  GateRig g;
  GateInputs in;
  in.auto_toggle = true;
  in.user_table = sensor_bit(13);
  EXPECT_EQ(g.step(in).selection, 0u) << "stopped: every sensor off";
  in.new_request = true;
  in.left = 30;
  in.right = -30;
  EXPECT_EQ(g.step(in).selection, watch_mask(7));
  in.auto_toggle = false;
  in.new_request = false;
  EXPECT_EQ(g.step(in).selection, watch_mask(7) | sensor_bit(13));
}

TEST(Gate, ReportsTheMaskAndTheTick) {
  GateRig g;
  g.gate.set_enabled(5);
  const GateDecision d = g.step();
  EXPECT_EQ(d.state.enabled, 5);
  EXPECT_EQ(d.state.tick, g.tick);
}

}  // namespace
}  // namespace robuter::emergency
