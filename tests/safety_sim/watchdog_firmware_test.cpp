// SPDX-License-Identifier: GPL-3.0-or-later
// Acceptance 2: AM curves and rotations select the seed's main sensor and watch set, firmware level.
#include <gtest/gtest.h>

#include <cstdio>
#include <set>
#include <string>

#include "modules/emergency/watchdog_sets.hpp"
#include "tests/safety_sim/support.hpp"

namespace robuter::test::safety_sim {
namespace {

// One motion per main sensor, written from the seed's emerg.c (r = (l+r)/(l−r)·300 mm against
// LIMIT12…LIMIT56; the special sets of 6, 7, 8, 18, 19, 20), not from the firmware's code.
struct Case {
  int left, right;      // AM wheel speeds, cm/s
  int main;             // expected main sensor
  std::set<int> watch;  // expected watch-dog set
};
const Case kCases[] = {
    {30, 30, 1, {1, 24, 2, 23, 3}},      // straight forward
    {30, 19, 2, {2, 1, 3, 24, 4}},       // r = 1336 mm: very soft curve right
    {30, 17, 3, {3, 2, 4, 1, 5}},        // r = 1085: soft
    {30, 15, 4, {4, 3, 5, 2, 6}},        // r = 900: medium
    {30, 13, 5, {5, 4, 6, 3, 7}},        // r = 759: hard
    {30, -10, 6, {6, 5, 7, 18, 24}},     // r = 150, left faster: special set
    {30, -30, 7, {7, 5, 6, 17, 18}},     // rotation clockwise (turning right): special set
    {-30, 10, 8, {8, 7, 9, 14, 20}},     // r = 150 backward, left faster: special set
    {-30, -14, 9, {9, 8, 10, 7, 11}},    // r = 825 backward
    {-30, -16, 10, {10, 9, 11, 8, 12}},  // r = 986
    {-30, -18, 11, {11, 10, 12, 9, 13}}, // r = 1200: not above LIMIT23
    {-30, -23, 12, {12, 11, 13, 10, 14}},// r = 2271
    {-30, -30, 13, {13, 12, 14, 11, 15}},// straight backward
    {-23, -30, 14, {14, 13, 15, 12, 16}},// r = −2271
    {-18, -30, 15, {15, 14, 16, 13, 17}},// r = −1200
    {-16, -30, 16, {16, 15, 17, 14, 18}},// r = −986
    {-14, -30, 17, {17, 16, 18, 15, 19}},// r = −825
    {10, -30, 18, {18, 17, 19, 12, 6}},  // r = −150, right faster: special set
    {-30, 30, 19, {19, 20, 21, 8, 9}},   // rotation anticlockwise: special set
    {-10, 30, 20, {20, 21, 19, 2, 8}},   // r = −150 forward, right faster: special set
    {13, 30, 21, {21, 20, 22, 19, 23}},  // r = −759
    {15, 30, 22, {22, 21, 23, 20, 24}},  // r = −900
    {17, 30, 23, {23, 22, 24, 21, 1}},   // r = −1085
    {19, 30, 24, {24, 23, 1, 22, 2}},    // r = −1336
};

// The table form of a set of sensor numbers (bit s−1 = sensor s).
std::uint32_t mask_of(const std::set<int>& s) {
  std::uint32_t m = 0;
  for (int k : s) m |= 1u << (k - 1);
  return m;
}

TEST(WatchdogSets, EveryMainSensorAndItsWatchSetFromAmOnTheWholeFirmware) {
  SimFirmware fw(ROBUTER_SHIPPED_WORLDS "/empty.toml", seed_rule_config());
  ASSERT_TRUE(fw.ok()) << fw.error();
  SafetyMonitor mon;
  mon.attach(fw);
  const sim::Pose centre{3.0, 3.0, 0.0};
  std::set<int> covered;
  for (const Case& c : kCases) {
    SCOPED_TRACE(testing::Message() << "AM " << c.left << " " << c.right);
    fw.sim().robot().place(centre);  // back to the middle of the arena, at rest
    const std::string am = "AM " + std::to_string(c.left) + " " + std::to_string(c.right);
    ASSERT_EQ(fw.ask(am), "ack");
    const auto& e = fw.bb().emergency.reader().peek();
    ASSERT_TRUE(fw.run_until([&] { return e.main_sensor != 0; }, 20)) << "no verdict on the request";
    EXPECT_EQ(e.main_sensor, c.main);
    EXPECT_EQ(e.watch, mask_of(c.watch)) << "published " << sensor_list(e.watch);
    EXPECT_EQ(e.safety_mm, 300u) << "30 cm/s on the faster wheel";
    // Granted once the five sensors have data: the drive gets exactly these speeds.
    ASSERT_TRUE(fw.run_until([&] {
      const Wheels w = commanded(fw);
      return w.left == c.left && w.right == c.right;
    }, 150)) << "never granted (held " << e.held << ", cause " << static_cast<int>(e.cause) << ")";
    EXPECT_FALSE(e.held);
    EXPECT_EQ(e.cause, EmergencyCause::none);
    const std::uint32_t fired = fw.bb().sonar_selection.reader().peek().active;
    EXPECT_EQ(fired & mask_of(c.watch), mask_of(c.watch)) << "the watch-dog sensors always fire";
    fw.run_ticks(30);  // moving for a moment with the set in force
    EXPECT_EQ(e.main_sensor, c.main);
    EXPECT_EQ(e.watch, mask_of(c.watch));
    covered.insert(e.main_sensor);
    std::printf("AM %4d %4d -> main %2d watch %s\n", c.left, c.right, e.main_sensor, sensor_list(e.watch).c_str());
    ASSERT_EQ(fw.ask("AM 0 0"), "ack");
    ASSERT_TRUE(fw.run_until([&] { return e.main_sensor == 0 && commanded(fw).zero(); }, 20));
    EXPECT_EQ(e.watch, 0u) << "stopped: no watch set";
  }
  EXPECT_EQ(covered.size(), 24u);
  EXPECT_EQ(fw.bb().emergency.reader().peek().trips, 0u) << "nothing trips in the empty arena";
  EXPECT_EQ(mon.violations(), 0u) << mon.first_violation;
  RecordProperty("main_sensors_covered", static_cast<int>(covered.size()));
}

}  // namespace
}  // namespace robuter::test::safety_sim
