// SPDX-License-Identifier: GPL-3.0-or-later
// Main sensor from curvature and watch-dog sets: every one of the 24 sensors, the seed's code
// transcribed verbatim as an oracle, ring arithmetic and the auto-toggle table.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <set>

#include "modules/emergency/watchdog_sets.hpp"

namespace robuter::emergency {
namespace {

// seed 002 emerg.c get_main_sensor(), transcribed with its literal tests ((left>0)&&(right>0)).
int seed_main_sensor(int left, int right) {
  const int DBW = 600;
  if (left == right) {
    if (left == 0) return 0;
    if (left < 0) return 13;
    return 1;
  }
  double r = (left + right) * 1.0 / (left - right);
  r = r * DBW / 2;
  const bool fwd = (left > 0) && (right > 0);
  if (std::fabs(r) > 2476) return fwd ? 1 : 13;
  if (std::fabs(r) > 1200) return fwd ? (r > 0 ? 2 : 24) : (r > 0 ? 12 : 14);
  if (std::fabs(r) > 1011) return fwd ? (r > 0 ? 3 : 23) : (r > 0 ? 11 : 15);
  if (std::fabs(r) > 864) return fwd ? (r > 0 ? 4 : 22) : (r > 0 ? 10 : 16);
  if (std::fabs(r) > 710) return fwd ? (r > 0 ? 5 : 21) : (r > 0 ? 9 : 17);
  if (r == 0) return left > 0 ? 7 : 19;
  if (left > right) return std::abs(left) > std::abs(right) ? 6 : 18;
  return std::abs(left) > std::abs(right) ? 8 : 20;
}

struct Case {
  int left, right;           // wheel speeds, cm/s
  int main;                  // expected main sensor
  std::set<int> watch;       // expected watch-dog set
};

// One motion for each of the 24 sensors (radius r = (l+r)/(l-r)·300 mm noted), with its set.
// One motion for each of the 24 sensors, with the radius r = (l+r)/(l-r)·300 mm and the set.
const Case kCases[] = {
    {30, 30, 1, {1, 24, 2, 23, 3}},            // straight forward
    {30, 19, 2, {2, 1, 3, 24, 4}},             // r = 1336: very soft curve right
    {30, 17, 3, {3, 2, 4, 1, 5}},              // r = 1085: soft
    {30, 15, 4, {4, 3, 5, 2, 6}},              // r = 900: medium
    {30, 13, 5, {5, 4, 6, 3, 7}},              // r = 759: hard
    {30, -10, 6, {6, 5, 7, 18, 24}},           // r = 150, left faster: special set
    {30, -30, 7, {7, 5, 6, 17, 18}},           // rotation clockwise: special set
    {-30, 10, 8, {8, 7, 9, 14, 20}},           // r = 150 backward, left faster: special set
    {-30, -14, 9, {9, 8, 10, 7, 11}},          // r = 825 backward
    {-30, -16, 10, {10, 9, 11, 8, 12}},        // r = 986
    {-30, -18, 11, {11, 10, 12, 9, 13}},       // r = 1200 exactly: not above LIMIT23
    {-30, -23, 12, {12, 11, 13, 10, 14}},      // r = 2271
    {-30, -30, 13, {13, 12, 14, 11, 15}},      // straight backward
    {-23, -30, 14, {14, 13, 15, 12, 16}},      // r = -2271
    {-18, -30, 15, {15, 14, 16, 13, 17}},      // r = -1200
    {-16, -30, 16, {16, 15, 17, 14, 18}},      // r = -986
    {-14, -30, 17, {17, 16, 18, 15, 19}},      // r = -825
    {10, -30, 18, {18, 17, 19, 12, 6}},        // r = -150, right faster: special set
    {-30, 30, 19, {19, 20, 21, 8, 9}},         // rotation anticlockwise: special set
    {-10, 30, 20, {20, 21, 19, 2, 8}},         // r = -150 forward, right faster: special set
    {13, 30, 21, {21, 20, 22, 19, 23}},        // r = -759
    {15, 30, 22, {22, 21, 23, 20, 24}},        // r = -900
    {17, 30, 23, {23, 22, 24, 21, 1}},         // r = -1085
    {19, 30, 24, {24, 23, 1, 22, 2}},          // r = -1336
};

std::set<int> as_set(const WatchSensors& w) { return {w.begin(), w.end()}; }

TEST(WatchdogSets, EverySensorFromItsCurvatureWithItsWatchSet) {
  std::set<int> covered;
  for (const Case& c : kCases) {
    SCOPED_TRACE(testing::Message() << "AM " << c.left << " " << c.right);
    EXPECT_EQ(seed_main_sensor(c.left, c.right), c.main) << "the table row disagrees with the seed";
    const int m = main_sensor(c.left, c.right, 600);
    EXPECT_EQ(m, c.main);
    EXPECT_EQ(as_set(watch_sensors(m)), c.watch);
    EXPECT_EQ(watch_sensors(m)[0], m) << "the main sensor comes first";
    std::uint32_t mask = 0;
    for (int s : c.watch) mask |= sensor_bit(s);
    EXPECT_EQ(watch_mask(m), mask);
    covered.insert(m);
  }
  EXPECT_EQ(covered.size(), 24u) << "the table must reach every sensor";
}

TEST(WatchdogSets, WatchSetOfEveryMainSensor) {
  const std::set<int> expected[25] = {
      {},
      {1, 24, 2, 23, 3}, {2, 1, 3, 24, 4}, {3, 2, 4, 1, 5}, {4, 3, 5, 2, 6}, {5, 4, 6, 3, 7},
      {6, 5, 7, 18, 24},                     // special
      {7, 5, 6, 17, 18},                     // special (rotation right)
      {8, 7, 9, 14, 20},                     // special
      {9, 8, 10, 7, 11}, {10, 9, 11, 8, 12}, {11, 10, 12, 9, 13}, {12, 11, 13, 10, 14},
      {13, 12, 14, 11, 15}, {14, 13, 15, 12, 16}, {15, 14, 16, 13, 17}, {16, 15, 17, 14, 18},
      {17, 16, 18, 15, 19},
      {18, 17, 19, 12, 6},                   // special
      {19, 20, 21, 8, 9},                    // special (rotation left)
      {20, 21, 19, 2, 8},                    // special
      {21, 20, 22, 19, 23}, {22, 21, 23, 20, 24}, {23, 22, 24, 21, 1}, {24, 23, 1, 22, 2},
  };
  int found[25] = {};
  for (int l = -60; l <= 60; ++l)
    for (int r = -60; r <= 60; ++r) {
      const int m = main_sensor(l, r, 600);
      if (m == 0) continue;
      if (found[m] == 0) found[m] = 1;
      else continue;
      SCOPED_TRACE(testing::Message() << "AM " << l << " " << r << " → sensor " << m);
      EXPECT_EQ(as_set(watch_sensors(m)), expected[m]);
      EXPECT_EQ(watch_sensors(m)[0], m) << "the main sensor comes first";
      std::uint32_t mask = 0;
      for (int s : expected[m]) mask |= sensor_bit(s);
      EXPECT_EQ(watch_mask(m), mask);
    }
  for (int s = 1; s <= 24; ++s) EXPECT_EQ(found[s], 1) << "no speeds reach sensor " << s;
  EXPECT_EQ(watch_mask(0), 0u);
  EXPECT_EQ(as_set(watch_sensors(0)), std::set<int>{0});
}

TEST(WatchdogSets, AgreesWithTheSeedOnEverySpeedPair) {
  int checked = 0;
  for (int l = -100; l <= 100; ++l)
    for (int r = -100; r <= 100; ++r) {
      ASSERT_EQ(main_sensor(l, r, 600), seed_main_sensor(l, r)) << "AM " << l << " " << r;
      ++checked;
    }
  EXPECT_EQ(checked, 201 * 201);
}

TEST(WatchdogSets, DirectionsOfTheSpecialCases) {
  EXPECT_EQ(main_sensor(0, 0, 600), 0);
  EXPECT_EQ(main_sensor(5, 5, 600), 1);
  EXPECT_EQ(main_sensor(-5, -5, 600), 13);
  EXPECT_EQ(main_sensor(10, -10, 600), 7);    // left forward, right back: turns right
  EXPECT_EQ(main_sensor(-10, 10, 600), 19);   // turns left
  EXPECT_EQ(main_sensor(0, 10, 600), 20);     // pivot on the left wheel, forward
  EXPECT_EQ(main_sensor(10, 0, 600), 6);      // pivot on the right wheel, forward
  EXPECT_EQ(main_sensor(0, -10, 600), 18);    // pivot backward on the left wheel
  EXPECT_EQ(main_sensor(-10, 0, 600), 8);     // pivot backward on the right wheel
  // Boundary: r exactly 1200 (l=5, r=3 → 8/2·300) is not "> LIMIT23", so soft curve, sensor 3.
  EXPECT_EQ(main_sensor(5, 3, 600), 3);
}

TEST(WatchdogSets, ForwardIsTheSignOfTheSpeedForOtherWheelBases) {
  // With a 2 m wheel base, |r| exceeds LIMIT56 with wheels of opposite sign: the robot moves
  // forward (l + r > 0) and must watch ahead, not behind as "both wheels positive" would say.
  const int m = main_sensor(10, -1, 2000);
  EXPECT_GE(m, 2);
  EXPECT_LE(m, 6);
}

TEST(WatchdogSets, RingArithmeticWraps) {
  EXPECT_EQ(sub24(1, 1), 24);
  EXPECT_EQ(sub24(1, 2), 23);
  EXPECT_EQ(sub24(5, 2), 3);
  EXPECT_EQ(add24(24, 1), 1);
  EXPECT_EQ(add24(23, 2), 1);
  EXPECT_EQ(add24(3, 2), 5);
}

TEST(AutoToggle, SelectionFollowsTheSeedsTwoModes) {
  const std::uint32_t watch = watch_mask(1);
  const std::uint32_t user = sensor_bit(13) | sensor_bit(7);
  // On: only the five watch-dog sensors, the user table ignored; nothing when stopped.
  EXPECT_EQ(select_sensors(user, true, watch, true), watch);
  EXPECT_EQ(select_sensors(user, true, 0, true), 0u);
  // Off: the user table OR the watch-dog set.
  EXPECT_EQ(select_sensors(user, false, watch, true), user | watch);
  EXPECT_EQ(select_sensors(kAllSensors, false, watch, true), kAllSensors);
  EXPECT_EQ(select_sensors(0, false, 0, true), 0u);
  // Ultrasonic detection off: the ring serves the user table alone.
  EXPECT_EQ(select_sensors(user, true, watch, false), user);
}

}  // namespace
}  // namespace robuter::emergency
