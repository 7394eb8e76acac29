// SPDX-License-Identifier: GPL-3.0-or-later
// Acceptance 4: bumper and communication-loss emergencies, latch and re-enable, BO/XE after a trip.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "modules/emergency/emergency.hpp"
#include "tests/safety_sim/support.hpp"

namespace robuter::test::safety_sim {
namespace {

// A wall whose near face is `gap` metres ahead of the robot's front face; nothing else.
std::string wall_world(double gap) {
  const double face = 1.0 + 0.695 + gap;
  return "[world]\nname = \"bump\"\nunits = \"m\"\n[start]\nx = 1.0\ny = 3.0\nheading_deg = 0.0\n"
         "[[rectangle]]\nname = \"wall\"\nmin = [" + std::to_string(face) + ", 1.0]\nmax = [" +
         std::to_string(face + 0.2) + ", 5.0]\n";
}

// Config with the ultrasonic detection masked off, so the bumper is what stops the robot.
Config bumper_only() {
  Config c;
  c.emergency.mask = kDetectBumper | kDetectComm;
  return c;
}

// Drives into the wall with the ultrasonic detection off; returns the ticks from first contact to
// zero speed at the drive (checked against one emergency period).
std::int64_t drive_into_wall(SimFirmware& fw) {
  std::uint64_t contact = 0, stopped = 0;
  fw.set_tick_observer([&] {
    const std::uint64_t tick = fw.kernel().tick() - 1;
    if (contact == 0 && fw.sim().robot().bumper()) contact = tick;
    if (contact != 0 && stopped == 0 && commanded(fw).zero()) stopped = tick;
  });
  EXPECT_EQ(fw.ask("AM 20 20"), "ack");
  EXPECT_TRUE(fw.run_until([&] { return stopped != 0; }, 2000)) << "never stopped on the bumper";
  fw.set_tick_observer(nullptr);
  return static_cast<std::int64_t>(stopped) - static_cast<std::int64_t>(contact);
}

TEST(Emergencies, BumperContactStopsLatchesAndXrIsRefusedUntilTheBumperIsFree) {
  TempWorld world(wall_world(1.0));
  SimFirmware fw(world.path(), bumper_only());
  ASSERT_TRUE(fw.ok()) << fw.error();
  auto xe = parse_xe(fw.ask("XE"));
  ASSERT_TRUE(xe);
  EXPECT_EQ(xe->enabled, 5) << "ultrasonic detection masked by the configuration";

  const std::int64_t reaction = drive_into_wall(fw);
  std::printf("bumper: contact to zero speed at the drive %lld ticks (%lld ms)\n", static_cast<long long>(reaction),
              static_cast<long long>(reaction * 10));
  RecordProperty("bumper_contact_to_stop_ticks", static_cast<int>(reaction));
  EXPECT_GE(reaction, 0);
  EXPECT_LE(reaction, 10) << "within one emergency period";
  const EmergencyState& e = fw.bb().emergency.reader().peek();
  EXPECT_EQ(e.cause, EmergencyCause::bumper);
  EXPECT_TRUE(e.latched);
  EXPECT_TRUE(fw.sim().robot().bumper()) << "still against the wall";

  const auto bo = parse_bo(fw.ask("BO"));
  ASSERT_TRUE(bo);
  EXPECT_EQ(bo->servo, 0) << "BO shows the servo off after the trip";
  xe = parse_xe(fw.ask("XE"));
  ASSERT_TRUE(xe);
  EXPECT_EQ(xe->latched, 1);
  EXPECT_EQ(xe->cause, "bumper");

  EXPECT_EQ(fw.ask("XR"), "error") << "refused while the bumper is pressed";
  EXPECT_EQ(fw.ask("AM -10 -10"), "error") << "motion refused while latched";
  EXPECT_EQ(fw.ask("ASN"), "error") << "servo-on refused while latched";
  fw.run_ticks(50);
  EXPECT_TRUE(commanded(fw).zero());
  EXPECT_TRUE(fw.bb().emergency.reader().peek().latched);

  // Someone pulls the robot 20 cm back: the bumper is free, the cause is gone.
  auto& robot = fw.sim().robot();
  robot.place(sim::Pose{robot.pose().x - 0.2, robot.pose().y, robot.pose().theta});
  ASSERT_FALSE(robot.bumper());
  fw.run_ticks(11);  // one emergency period: the verdict says clearable
  EXPECT_TRUE(fw.bb().emergency.reader().peek().clearable);
  EXPECT_EQ(fw.ask("XR"), "ack");
  fw.run_ticks(2);
  xe = parse_xe(fw.ask("XE"));
  ASSERT_TRUE(xe);
  EXPECT_EQ(xe->latched, 0);
  EXPECT_EQ(xe->cause, "none");

  // The old 20 cm/s never comes back by itself.
  const double x0 = robot.pose().x;
  fw.run_ticks(300);
  EXPECT_TRUE(commanded(fw).zero()) << "a re-enable never moves the robot";
  EXPECT_NEAR(robot.pose().x, x0, 1e-9);
  // A new request moves again (backwards, away from the wall).
  EXPECT_EQ(fw.ask("AM -10 -10"), "ack");
  ASSERT_TRUE(fw.run_until([&] { return commanded(fw).left == -10; }, 50));
  fw.run_ticks(100);
  EXPECT_LT(robot.pose().x, x0 - 0.05);
  EXPECT_EQ(fw.ask("AM 0 0"), "ack");
}

TEST(Emergencies, WithTheBumperMaskedOffXrClearsAndTheRobotBacksAway) {
  TempWorld world(wall_world(0.5));
  SimFirmware fw(world.path(), bumper_only());
  ASSERT_TRUE(fw.ok()) << fw.error();
  const std::int64_t reaction = drive_into_wall(fw);
  EXPECT_LE(reaction, 10);
  ASSERT_TRUE(fw.bb().emergency.reader().peek().latched);
  ASSERT_TRUE(fw.sim().robot().bumper());
  EXPECT_EQ(fw.ask("XR"), "error");
  // docs/SAFETY.md §4: switch the bumper detection off, XR, back away.
  auto* em = fw.module<EmergencyModule>("emergency");
  ASSERT_NE(em, nullptr);
  em->set_enabled(4);
  fw.run_ticks(11);
  EXPECT_EQ(fw.ask("XR"), "ack");
  fw.run_ticks(2);
  EXPECT_FALSE(fw.bb().emergency.reader().peek().latched);
  EXPECT_EQ(fw.ask("AM -10 -10"), "ack");
  ASSERT_TRUE(fw.run_until([&] { return !fw.sim().robot().bumper(); }, 200)) << "backs off the wall";
  fw.run_ticks(50);
  EXPECT_EQ(fw.ask("AM 0 0"), "ack");
  em->set_enabled(5);
  fw.run_ticks(20);
  EXPECT_FALSE(fw.bb().emergency.reader().peek().latched);
  EXPECT_EQ(fw.bb().emergency.reader().peek().cause, EmergencyCause::none);
}

TEST(Emergencies, SilenceBeyondTheCommunicationLimitStopsWithCommLoss) {
  Config cfg;
  cfg.emergency.comm_limit_ticks = 300;
  SimFirmware fw(ROBUTER_SHIPPED_WORLDS "/empty.toml", cfg);
  ASSERT_TRUE(fw.ok()) << fw.error();
  ASSERT_EQ(fw.ask("AM 10 10"), "ack");
  const std::uint64_t last = fw.bb().link_status.reader().peek().last_message_tick;
  // A start from rest waits for two full ring passes (docs/SAFETY.md §13), well inside the limit.
  ASSERT_TRUE(fw.run_until([&] { return commanded(fw).left == 10; }, 200));
  std::uint64_t stopped = 0;
  ASSERT_TRUE(fw.run_until(
      [&] {
        if (commanded(fw).zero()) stopped = fw.kernel().tick() - 1;
        return stopped != 0;
      },
      400));
  const std::int64_t silence = static_cast<std::int64_t>(stopped - last);
  std::printf("comm loss: limit 300 ticks, stopped after %lld ticks of silence\n", static_cast<long long>(silence));
  RecordProperty("comm_loss_stop_after_ticks", static_cast<int>(silence));
  EXPECT_GT(silence, 300);
  EXPECT_LE(silence, 300 + 10) << "within one emergency period after the limit";
  const EmergencyState& e = fw.bb().emergency.reader().peek();
  EXPECT_EQ(e.cause, EmergencyCause::comm_loss);
  EXPECT_TRUE(e.latched);
  EXPECT_FALSE(fw.sim().drive().servo());

  // The client comes back: BO and XE show the trip (and end the silence).
  const auto bo = parse_bo(fw.ask("BO"));
  ASSERT_TRUE(bo);
  EXPECT_EQ(bo->servo, 0);
  const auto xe = parse_xe(fw.ask("XE"));
  ASSERT_TRUE(xe);
  EXPECT_EQ(xe->latched, 1);
  EXPECT_EQ(xe->cause, "comm-loss");
  EXPECT_EQ(fw.ask("AM 10 10"), "error") << "refused while latched";
  // Clearable once the emergency has seen the link alive again and the robot at rest (two
  // executor postures apart: at most about three emergency periods after the stop).
  EXPECT_TRUE(fw.run_until([&] { return fw.bb().emergency.reader().peek().clearable; }, 40));
  EXPECT_EQ(fw.ask("XR"), "ack");
  const double x0 = fw.sim().robot().pose().x;
  fw.run_ticks(250);
  EXPECT_TRUE(commanded(fw).zero()) << "the old speed never resumes";
  EXPECT_NEAR(fw.sim().robot().pose().x, x0, 1e-9);
  EXPECT_EQ(fw.ask("AM 10 10"), "ack");
  EXPECT_TRUE(fw.run_until([&] { return commanded(fw).left == 10; }, 100)) << "a new AM moves again";
}

// docs/SAFETY.md §4: an obstacle is an event, "gone once the robot has stopped" — an XR sent
// while the robot still brakes is refused, and no new motion can start before it is at rest.
TEST(Emergencies, AfterAnObstacleTripXrWaitsUntilTheRobotHasStopped) {
  SimFirmware fw(ROBUTER_SAFETY_SIM_WORLDS "/wall_ahead.toml", seed_rule_config());
  ASSERT_TRUE(fw.ok()) << fw.error();
  SafetyMonitor mon;
  mon.attach(fw);
  auto& robot = fw.sim().robot();
  ASSERT_EQ(fw.ask("AM 80 80"), "ack");
  ASSERT_TRUE(fw.run_until([&] { return fw.bb().emergency.reader().peek().latched; }, 2000));
  ASSERT_GT(robot.wheel_speeds().left, 0.3) << "still braking from 80 cm/s";
  int refused = 0;
  while (robot.wheel_speeds().left > 0.0 || robot.wheel_speeds().right > 0.0) {
    ASSERT_EQ(fw.ask("XR"), "error") << "re-enabled at " << robot.wheel_speeds().left << " m/s";
    ++refused;
    fw.run_ticks(5);
  }
  fw.run_ticks(30);  // at rest for an executor and an emergency period
  EXPECT_EQ(fw.ask("XR"), "ack");
  std::printf("obstacle trip at 80 cm/s: %d XR refused while braking, accepted at rest\n", refused);
  EXPECT_GT(refused, 0);
  // Turning away now is safe: the robot is at rest, the rotation is judged on its own sensors.
  EXPECT_EQ(fw.ask("AM 10 -10"), "ack");
  fw.run_ticks(200);
  EXPECT_EQ(mon.violations(), 0u) << mon.first_violation;
}

// The same with latch = false: the emergency clears by itself, but only once the robot is at
// rest; a request sent while it brakes is not granted.
TEST(Emergencies, WithoutLatchNoNewMotionIsGrantedWhileTheRobotStillBrakes) {
  Config cfg = seed_rule_config();
  cfg.emergency.latch = false;
  SimFirmware fw(ROBUTER_SAFETY_SIM_WORLDS "/wall_ahead.toml", cfg);
  ASSERT_TRUE(fw.ok()) << fw.error();
  SafetyMonitor mon;
  mon.attach(fw);
  auto& robot = fw.sim().robot();
  ASSERT_EQ(fw.ask("AM 80 80"), "ack");
  ASSERT_TRUE(fw.run_until([&] { return fw.bb().emergency.reader().peek().trips > 0; }, 2000));
  ASSERT_GT(robot.wheel_speeds().left, 0.3);
  EXPECT_EQ(fw.ask("AM 30 -30"), "ack") << "not latched: the request is taken";
  std::uint64_t granted_while_braking = 0;
  while (robot.wheel_speeds().left > 0.0 && robot.wheel_speeds().right > 0.0) {
    if (!commanded(fw).zero()) ++granted_while_braking;
    fw.step();
  }
  EXPECT_EQ(granted_while_braking, 0u) << "a motion was granted while the robot still braked";
  EXPECT_EQ(mon.violations(), 0u) << mon.first_violation;
}

TEST(Emergencies, StopByteReachesTheDriveInTheTickItIsRead) {
  SimFirmware fw(ROBUTER_SHIPPED_WORLDS "/empty.toml", seed_rule_config());
  ASSERT_TRUE(fw.ok()) << fw.error();
  ASSERT_EQ(fw.ask("AM 20 20"), "ack");
  ASSERT_TRUE(fw.run_until([&] { return commanded(fw).left == 20; }, 100));
  const std::uint64_t sent = fw.kernel().tick();  // the next tick to run
  fw.send_raw("\x18");
  ASSERT_TRUE(fw.run_until([&] { return commanded(fw).zero(); }, 20));
  const std::uint64_t stopped = fw.kernel().tick() - 1;
  std::printf("stop byte: written before tick %llu, zero speed in tick %llu\n", static_cast<unsigned long long>(sent),
              static_cast<unsigned long long>(stopped));
  EXPECT_EQ(stopped, sent) << "the link triggers the emergency, which triggers the executor";
  const auto xe = parse_xe(fw.ask("XE"));
  ASSERT_TRUE(xe);
  EXPECT_EQ(xe->cause, "stop-byte");
  EXPECT_EQ(xe->latched, 1);
  EXPECT_EQ(fw.ask("XR"), "error") << "still braking from 20 cm/s: the cause is not gone yet";
  const auto& robot = fw.sim().robot();
  ASSERT_TRUE(fw.run_until([&] { return robot.wheel_speeds().left == 0.0; }, 100));
  fw.run_ticks(30);
  EXPECT_EQ(fw.ask("XR"), "ack") << "an event cause is gone once the robot has stopped";
  fw.run_ticks(100);
  EXPECT_TRUE(commanded(fw).zero());
}

}  // namespace
}  // namespace robuter::test::safety_sim
