// SPDX-License-Identifier: GPL-3.0-or-later
// Acceptance 1: straight at a wall 4 m ahead at 10, 30 and 60 cm/s, the robot stops short of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "tests/safety_sim/support.hpp"

namespace robuter::test::safety_sim {
namespace {

constexpr double kWallFaceX = 5.695;  // the wall's near face in worlds/wall_ahead.toml, m

// What one run at the wall gave.
struct WallRun {
  double clearance_mm = 0;      // front face to the wall at rest, mm
  double min_clearance_mm = 0;  // smallest true body-to-wall distance over the whole run, mm
  int trip_range_mm = 0;        // the reading that tripped, mm
  int trip_sensor = 0;          // the sensor that tripped
  std::uint32_t safety_mm = 0;  // the safety distance in force, mm
  double peak_speed = 0;        // fastest forward speed reached, cm/s
  double seconds = 0;           // simulated time from AM to rest, s
};

// Drives straight at the wall at `speed` cm/s until the emergency stops the robot and it is at
// rest; checks on every tick that nothing touched and no speed reached the drive after the trip.
WallRun run_at_wall(int speed) {
  WallRun out;
  SimFirmware fw(ROBUTER_SAFETY_SIM_WORLDS "/wall_ahead.toml", seed_rule_config());
  EXPECT_TRUE(fw.ok()) << fw.error();
  if (!fw.ok()) return out;
  SafetyMonitor mon;
  mon.attach(fw);
  const auto& robot = fw.sim().robot();
  const double t0 = fw.seconds();
  EXPECT_EQ(fw.ask("AM " + std::to_string(speed) + " " + std::to_string(speed)), "ack");
  const int max_ticks = 4000 * 100 / speed + 1000;  // 4 m at `speed`, plus the start
  EXPECT_TRUE(fw.run_until(
      [&] {
        out.peak_speed = std::max(out.peak_speed, 50.0 * (robot.wheel_speeds().left + robot.wheel_speeds().right));
        return fw.bb().emergency.reader().peek().latched;
      },
      max_ticks))
      << "never stopped at " << speed << " cm/s";
  const EmergencyState e = fw.bb().emergency.reader().peek();
  const auto& ranges = fw.bb().ranges.reader().peek();
  out.trip_sensor = e.sensor;
  out.trip_range_mm = e.sensor > 0 ? ranges.mm[static_cast<std::size_t>(e.sensor - 1)] : 0;
  const int main = 1;
  EXPECT_EQ(e.cause, EmergencyCause::obstacle);
  EXPECT_EQ(e.main_sensor, main) << "straight forward: sensor 1 leads";
  out.safety_mm = e.safety_mm;
  EXPECT_TRUE(commanded(fw).zero()) << "speeds zeroed at the trip";
  EXPECT_FALSE(fw.sim().drive().servo()) << "an emergency switches the servo off";
  // Let the robot come to rest at its deceleration limit, then a while more.
  EXPECT_TRUE(fw.run_until([&] { return robot.wheel_speeds().left == 0.0 && robot.wheel_speeds().right == 0.0; }, 300));
  fw.run_ticks(100);
  out.seconds = fw.seconds() - t0;
  sim::Vec2 corners[4];
  sim::footprint_corners(robot.params().geometry, robot.pose(), corners);
  double front = -1e9;
  for (const auto& c : corners) front = std::max(front, c.x());
  out.clearance_mm = (kWallFaceX - front) * 1000.0;
  out.min_clearance_mm = mon.min_clearance_us_on * 1000.0;
  EXPECT_EQ(mon.contact_us_on, 0u) << mon.first_violation;
  EXPECT_EQ(mon.violations(), 0u) << mon.first_violation;
  EXPECT_FALSE(robot.bumper());
  EXPECT_GT(out.clearance_mm, 0.0) << "the body must not touch the wall";
  EXPECT_GT(out.min_clearance_mm, 0.0) << "the true body never reached the wall";
  EXPECT_LT(out.clearance_mm, out.safety_mm) << "stopped by the watch, not before it";
  EXPECT_NEAR(out.peak_speed, speed, 1.0) << "the robot really drove at the speed asked";
  return out;
}

// 10, 30 and 60 cm/s are the acceptance criterion; 100 cm/s (robot.max_speed_cm_s) shows the
// margin left at the fastest speed the link accepts.
TEST(WallStop, StraightAtAWallAt10_30And60CmPerSecondStopsWithoutTouching) {
  std::printf("speed  safety  trip sensor/range  clearance at rest  min clearance  time to rest\n");
  for (int speed : {10, 30, 60, 100}) {
    SCOPED_TRACE(testing::Message() << speed << " cm/s");
    const WallRun r = run_at_wall(speed);
    std::printf("%3d cm/s  %4u mm  %2d / %4d mm  %7.1f mm  %7.1f mm  %5.2f s\n", speed, r.safety_mm, r.trip_sensor,
                r.trip_range_mm, r.clearance_mm, r.min_clearance_mm, r.seconds);
    RecordProperty("clearance_mm_at_" + std::to_string(speed) + "_cm_s", std::to_string(static_cast<int>(r.clearance_mm)));
    RecordProperty("trip_range_mm_at_" + std::to_string(speed) + "_cm_s", std::to_string(r.trip_range_mm));
  }
}

}  // namespace
}  // namespace robuter::test::safety_sim
