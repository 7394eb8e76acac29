// SPDX-License-Identifier: GPL-3.0-or-later
// Safety distance (seed get_us_limit) and the watch-dog verdict: clear, hold, obstacle.
#include <gtest/gtest.h>

#include "modules/emergency/obstacle_check.hpp"

namespace robuter::emergency {
namespace {

TEST(SafetyDistance, TenMillimetresPerCentimetrePerSecondAtLeast220) {
  EXPECT_EQ(safety_distance_mm(0, 0, 220, 10), 220u);
  EXPECT_EQ(safety_distance_mm(21, 21, 220, 10), 220u);
  EXPECT_EQ(safety_distance_mm(22, 5, 220, 10), 220u);
  EXPECT_EQ(safety_distance_mm(23, 5, 220, 10), 230u);
  EXPECT_EQ(safety_distance_mm(5, 50, 220, 10), 500u);     // the faster wheel counts
  EXPECT_EQ(safety_distance_mm(-80, 10, 220, 10), 800u);   // whatever its sign
  EXPECT_EQ(safety_distance_mm(-100, -100, 220, 10), 1000u);
}

TEST(SafetyDistance, Configurable) {
  EXPECT_EQ(safety_distance_mm(10, 10, 300, 10), 300u);
  EXPECT_EQ(safety_distance_mm(50, 10, 300, 15), 750u);
  EXPECT_EQ(safety_distance_mm(2'000'000'000, 0, 220, 10), 0xFFFFFFFFu);  // saturates
}

UltrasonicRanges ranges_all(std::uint16_t mm, std::uint64_t tick) {
  UltrasonicRanges r;
  r.mm.fill(mm);
  r.read_tick.fill(tick);
  return r;
}

TEST(WatchVerdict, ClearWhenEveryReadingIsBeyondTheSafetyDistance) {
  const auto r = ranges_all(1000, 100);
  const WatchVerdict v = check_watch(watch_sensors(1), r, 220, 100, 300);
  EXPECT_EQ(v.result, WatchResult::clear);
  EXPECT_EQ(v.sensor, 0);
}

TEST(WatchVerdict, AReadingAtOrUnderTheSafetyDistanceIsAnObstacle) {
  auto r = ranges_all(1000, 100);
  r.mm[23 - 1] = 221;
  EXPECT_EQ(check_watch(watch_sensors(1), r, 220, 100, 300).result, WatchResult::clear);
  r.mm[23 - 1] = 220;  // the seed passes only "> limit"
  const WatchVerdict v = check_watch(watch_sensors(1), r, 220, 100, 300);
  EXPECT_EQ(v.result, WatchResult::obstacle);
  EXPECT_EQ(v.sensor, 23);
}

TEST(WatchVerdict, OnlyTheWatchDogSensorsCount) {
  auto r = ranges_all(1000, 100);
  r.mm[13 - 1] = 50;  // behind the robot
  EXPECT_EQ(check_watch(watch_sensors(1), r, 220, 100, 300).result, WatchResult::clear);
  EXPECT_EQ(check_watch(watch_sensors(13), r, 220, 100, 300).result, WatchResult::obstacle);
}

TEST(WatchVerdict, NoReadingYetHolds) {
  auto r = ranges_all(1000, 100);
  r.mm[2 - 1] = 0;
  const WatchVerdict v = check_watch(watch_sensors(1), r, 220, 100, 300);
  EXPECT_EQ(v.result, WatchResult::hold);
  EXPECT_EQ(v.sensor, 2);
}

TEST(WatchVerdict, AnObstacleWinsOverMissingData) {
  auto r = ranges_all(1000, 100);
  r.mm[2 - 1] = 0;
  r.mm[3 - 1] = 100;
  const WatchVerdict v = check_watch(watch_sensors(1), r, 220, 100, 300);
  EXPECT_EQ(v.result, WatchResult::obstacle);
  EXPECT_EQ(v.sensor, 3);
}

TEST(WatchVerdict, AStaleReadingCountsAsMissing) {
  auto r = ranges_all(1000, 100);
  EXPECT_EQ(check_watch(watch_sensors(1), r, 220, 400, 300).result, WatchResult::clear);   // 300 old: fresh
  EXPECT_EQ(check_watch(watch_sensors(1), r, 220, 401, 300).result, WatchResult::hold);    // 301 old: stale
}

}  // namespace
}  // namespace robuter::emergency
