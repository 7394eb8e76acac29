// SPDX-License-Identifier: GPL-3.0-or-later
// The three modules together in a kernel on a virtual clock with the seed's table: stops reach
// the drive in the tick their cause is read, hold and resume, trips, latch and re-enable,
// auto-toggle, servo requests, go-to through the gate, shut-down.
#include <gtest/gtest.h>

#include "modules/emergency/watchdog_sets.hpp"
#include "tests/safety/rig.hpp"

namespace robuter::test {
namespace {

// Steps until every sensor has a reading (the first full scan, about 60 ticks).
void warm_up(Rig& r) {
  ASSERT_TRUE(r.ok);
  ASSERT_TRUE(r.step_until([&] { return r.ranges().scans >= 1; }, 200));
}

// Sends AM and steps until the drive moves at those speeds.
void move(Rig& r, std::int32_t l, std::int32_t rr) {
  r.link.am(l, rr);
  ASSERT_TRUE(r.step_until([&] { return r.drive.moving() && r.drive.left() == l && r.drive.right() == rr; }, 30))
      << "AM " << l << " " << rr << " never reached the drive";
}

TEST(Core, AnObstacleStopReachesTheDriveInTheTickTheRangeWasRead) {
  Rig r(seed_config());
  warm_up(r);
  move(r, 30, 30);
  r.ring.world[0] = 250;  // sensor 1, under 300 mm at 30 cm/s
  ASSERT_TRUE(r.step_until([&] { return r.state().cause != EmergencyCause::none; }, 100));
  const std::uint64_t read = r.ranges().read_tick[0];
  EXPECT_EQ(r.ranges().mm[0], 250);
  EXPECT_EQ(r.state().cause, EmergencyCause::obstacle);
  EXPECT_EQ(r.state().sensor, 1);
  EXPECT_EQ(r.state().tick, read) << "judged in the tick it was read";
  EXPECT_FALSE(r.drive.servo());
  EXPECT_FALSE(r.drive.moving());
  const DriveCommand& last = r.drive.command(r.drive.commands() - 1);
  EXPECT_TRUE(last.servo_call);
  EXPECT_FALSE(last.on);
  EXPECT_EQ(last.tick, read) << "the stop reached the drive within the same tick";
  EXPECT_EQ(r.drive.violations(), 0u) << r.drive.first_violation();
}

TEST(Core, HoldOnMissingDataThenResume) {
  Rig r(seed_config());
  warm_up(r);
  r.link.uu(true);  // auto-toggle: stopped, every sensor goes off
  r.step(60);
  for (int s = 1; s <= 24; ++s) ASSERT_EQ(r.ranges().mm[s - 1], 0) << s;
  r.link.am(20, 20);
  ASSERT_TRUE(r.step_until([&] { return r.state().held; }, 20));
  EXPECT_FALSE(r.drive.moving()) << "held: no motion before the data";
  EXPECT_FALSE(r.command().stop) << "a hold is not an emergency";
  ASSERT_TRUE(r.step_until([&] { return r.drive.moving(); }, 100)) << "resumes once the watch-dog sensors read";
  EXPECT_FALSE(r.state().held);
  EXPECT_EQ(r.drive.left(), 20);
  for (int s : emergency::watch_sensors(1)) EXPECT_GT(r.ranges().mm[s - 1], 0) << s;
  EXPECT_EQ(r.drive.violations(), 0u) << r.drive.first_violation();
}

TEST(Core, AutoToggleFiresOnlyTheWatchDogSensors) {
  Rig r(seed_config());
  warm_up(r);
  r.link.uu(true);
  r.step(60);
  const std::uint64_t before = r.ring.firings();
  r.step(100);
  EXPECT_EQ(r.ring.firings(), before) << "stopped: nothing fires";
  move(r, 20, 20);
  r.step(100);
  ASSERT_GT(r.ring.firings(), before);
  for (std::uint64_t i = r.ring.firings() - 4; i < r.ring.firings(); ++i) {
    const auto& f = r.ring.firing(i);
    // Sensors 1, 2, 3 on node 0 and 23, 24 on node 5.
    if (f.node == 0) EXPECT_EQ(f.mask, 0b0111);
    else if (f.node == 5) EXPECT_EQ(f.mask, 0b1100);
    else ADD_FAILURE() << "node " << f.node << " fired";
  }
  EXPECT_EQ(r.bb.sonar_selection.reader().peek().active, emergency::watch_mask(1));
  r.link.uu(false);
  r.link.ut(emergency::sensor_bit(13));
  r.step(20);
  EXPECT_EQ(r.bb.sonar_selection.reader().peek().active, emergency::watch_mask(1) | emergency::sensor_bit(13));
}

TEST(Core, BumperStopsAndLatches) {
  Rig r(seed_config());
  warm_up(r);
  move(r, 20, 20);
  r.bumpers.state = 1;
  ASSERT_TRUE(r.step_until([&] { return !r.drive.moving(); }, 11)) << "within one emergency period";
  EXPECT_EQ(r.state().cause, EmergencyCause::bumper);
  EXPECT_TRUE(r.state().latched);
  EXPECT_FALSE(r.drive.servo());
}

TEST(Core, CommunicationLossAfterTheLimit) {
  Config c = seed_config();
  c.emergency.comm_limit_ticks = 300;
  Rig r(c);
  warm_up(r);
  move(r, 10, 10);
  const std::uint64_t last = r.bb.link_status.reader().peek().last_message_tick;
  ASSERT_TRUE(r.step_until([&] { return !r.drive.moving(); }, 400));
  EXPECT_EQ(r.state().cause, EmergencyCause::comm_loss);
  EXPECT_GT(r.kernel.tick() - last, 300u);
  EXPECT_LE(r.kernel.tick() - last, 300u + 12u);
}

TEST(Core, StopByteStopsInTheSameTickWhenTheLinkTriggers) {
  Rig r(seed_config());
  warm_up(r);
  move(r, 40, 40);
  r.link.stop_byte();
  r.kernel.trigger(&r.emergency);  // as a link does when it takes the stop byte
  const std::uint64_t t = r.kernel.tick();
  r.step();
  EXPECT_FALSE(r.drive.moving());
  EXPECT_EQ(r.drive.command(r.drive.commands() - 1).tick, t);
  EXPECT_EQ(r.state().cause, EmergencyCause::stop_byte);
  EXPECT_TRUE(r.state().latched);
}

TEST(Core, LatchHoldsUntilReenableAndTheOldSpeedNeverResumes) {
  Rig r(seed_config());
  warm_up(r);
  move(r, 30, 30);
  r.ring.world[0] = 200;
  ASSERT_TRUE(r.step_until([&] { return r.state().latched; }, 100));
  r.ring.world[0] = 3000;
  r.step(100);
  EXPECT_TRUE(r.state().latched);
  EXPECT_TRUE(r.state().clearable);
  r.link.am(30, 30);  // a client that ignores the refusal
  r.step(30);
  EXPECT_FALSE(r.drive.moving()) << "requests are dropped while latched";
  r.link.xr();
  r.step(20);
  EXPECT_FALSE(r.state().latched);
  EXPECT_FALSE(r.drive.moving()) << "a re-enable alone never moves the robot";
  r.step(100);
  EXPECT_FALSE(r.drive.moving());
  move(r, 30, 30);
  EXPECT_EQ(r.drive.violations(), 0u) << r.drive.first_violation();
}

TEST(Core, WithoutLatchTheOldSpeedStillNeverResumes) {
  Config c = seed_config();
  c.emergency.latch = false;
  Rig r(c);
  warm_up(r);
  move(r, 20, 20);
  r.bumpers.state = 1;
  ASSERT_TRUE(r.step_until([&] { return !r.drive.moving(); }, 11));
  r.bumpers.state = 0;
  r.step(20);
  EXPECT_EQ(r.state().cause, EmergencyCause::none) << "clears by itself";
  EXPECT_FALSE(r.state().latched);
  r.step(200);
  EXPECT_FALSE(r.drive.moving());
  move(r, 20, 20);
}

TEST(Core, ServoOnDoesNotMoveAnything) {
  Rig r(seed_config());
  warm_up(r);
  r.link.as(true);
  r.step(20);
  EXPECT_TRUE(r.drive.servo());
  EXPECT_FALSE(r.drive.moving());
  move(r, 10, 10);
  r.link.as(true);  // while moving: the motion stops, the servo stays on
  ASSERT_TRUE(r.step_until([&] { return !r.drive.moving(); }, 20));
  EXPECT_TRUE(r.drive.servo());
  move(r, 10, 10);
  r.link.as(false);
  EXPECT_TRUE(r.step_until([&] { return !r.drive.servo(); }, 11)) << "at the executor's next activation";
  r.step(50);
  EXPECT_FALSE(r.drive.moving()) << "servo off ends the motion";
}

TEST(Core, ServoOnIsRefusedWhileLatched) {
  Rig r(seed_config());
  warm_up(r);
  r.link.stop_byte();
  r.step(20);
  ASSERT_TRUE(r.state().latched);
  r.link.as(true);
  r.step(20);
  EXPECT_FALSE(r.drive.servo());
  EXPECT_EQ(r.drive.violations(), 0u) << r.drive.first_violation();
}

TEST(Core, GoToDrivesThroughTheGateAndArrives) {
  Rig r(seed_config());
  warm_up(r);
  r.link.aw(5000, 2000, 9000);  // 50 cm ahead, 20 cm left, facing +y
  r.step(10);
  EXPECT_TRUE(r.executor.go_to().active());
  EXPECT_GT(r.bb.go_to_motion.reader().generation(), 0u) << "asks the gate, never the drive";
  ASSERT_TRUE(r.step_until([&] { return !r.executor.go_to().active(); }, 6000));
  r.step(30);
  const Posture& p = r.posture();
  EXPECT_NEAR(p.x, 5000, 200);
  EXPECT_NEAR(p.y, 2000, 200);
  EXPECT_NEAR(p.theta, 9000, 200);
  EXPECT_FALSE(r.drive.moving());
  EXPECT_EQ(r.command().source, MotionSource::go_to);
  EXPECT_EQ(r.drive.violations(), 0u) << r.drive.first_violation();
}

TEST(Core, GoToIsCancelledByANewerMotionRequest) {
  Rig r(seed_config());
  warm_up(r);
  r.link.aw(50000, 0, 0);
  ASSERT_TRUE(r.step_until([&] { return r.drive.moving(); }, 50));
  r.link.am(0, 0);
  r.step(25);
  EXPECT_FALSE(r.executor.go_to().active());
  EXPECT_FALSE(r.drive.moving());
  r.step(100);
  EXPECT_FALSE(r.drive.moving());
}

TEST(Core, GoToIsCancelledByAnEmergencyAndNeverResumes) {
  Rig r(seed_config());
  warm_up(r);
  r.link.aw(50000, 0, 0);
  ASSERT_TRUE(r.step_until([&] { return r.drive.moving(); }, 50));
  r.bumpers.state = 1;
  ASSERT_TRUE(r.step_until([&] { return !r.drive.moving(); }, 11));
  r.step(10);
  EXPECT_FALSE(r.executor.go_to().active());
  r.bumpers.state = 0;
  r.link.xr();
  r.step(200);
  EXPECT_FALSE(r.drive.moving());
}

TEST(Core, OdometrySetMovesTheFrame) {
  Rig r(seed_config());
  warm_up(r);
  r.link.ac(12345, -500, 9000);
  r.step(10);
  EXPECT_EQ(r.posture().x, 12345);
  EXPECT_EQ(r.posture().y, -500);
  EXPECT_EQ(r.posture().theta, 9000);
}

TEST(Core, DriveFaultSwitchesTheServoOffAndLatches) {
  Rig r(seed_config());
  warm_up(r);
  move(r, 10, 10);
  r.drive.set_health(hal::DriveHealth::fault);
  r.step(25);
  EXPECT_FALSE(r.drive.servo());
  EXPECT_EQ(r.state().cause, EmergencyCause::drive_fault);
  EXPECT_TRUE(r.state().latched);
}

TEST(Core, MotionTimeoutStopsAStaleMotion) {
  Config c = seed_config();
  c.emergency.motion_timeout_ms = 500;
  Rig r(c);
  warm_up(r);
  move(r, 10, 10);
  ASSERT_TRUE(r.step_until([&] { return !r.drive.moving(); }, 70));
  EXPECT_EQ(r.state().cause, EmergencyCause::motion_timeout);
}

TEST(Core, ShutdownZeroesAndSwitchesTheServoOff) {
  Rig r(seed_config());
  warm_up(r);
  move(r, 10, 10);
  r.kernel.shutdown();
  EXPECT_FALSE(r.drive.servo());
  EXPECT_FALSE(r.drive.moving());
  const DriveCommand& last = r.drive.command(r.drive.commands() - 1);
  EXPECT_TRUE(last.servo_call);
  EXPECT_FALSE(last.on);
}

TEST(Core, TimingStatisticsArePublished) {
  Rig r(seed_config());
  warm_up(r);
  r.step(200);
  const UltrasonicTiming& t = r.bb.us_timing.reader().peek();
  EXPECT_EQ(t.mean_node_ticks, 8u) << "period 4: fire, read 4 ticks later, next fire after the 3-tick delay";
  EXPECT_EQ(t.mean_scan_ticks, 48u);
}

}  // namespace
}  // namespace robuter::test
