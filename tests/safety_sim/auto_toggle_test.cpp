// SPDX-License-Identifier: GPL-3.0-or-later
// Acceptance 7: auto-toggle fires the watch set only (none stopped); UT OR-ed when off, kept when on.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>

#include "modules/emergency/watchdog_sets.hpp"
#include "tests/safety_sim/support.hpp"

namespace robuter::test::safety_sim {
namespace {

// A UT line for a table (sensor 1 first).
std::string ut(std::uint32_t m) {
  std::string line = "UT";
  for (int s = 1; s <= 24; ++s) line += (m & (1u << (s - 1))) ? '1' : '0';
  return line;
}

// The sensors that fired: lets the ring settle on the table in force (the current scan ends,
// the next starts with it), then returns the sensors whose read tick moved during `window` ticks.
std::uint32_t fired_sensors(SimFirmware& fw, int window = 150) {
  fw.run_ticks(60);
  const auto before = fw.bb().ranges.reader().peek().read_tick;
  fw.run_ticks(window);
  const auto& after = fw.bb().ranges.reader().peek().read_tick;
  std::uint32_t m = 0;
  for (int s = 1; s <= 24; ++s)
    if (after[static_cast<std::size_t>(s - 1)] != before[static_cast<std::size_t>(s - 1)]) m |= 1u << (s - 1);
  return m;
}

// The table the emergency module tells the ring to fire.
std::uint32_t selection(SimFirmware& fw) { return fw.bb().sonar_selection.reader().peek().active; }

TEST(AutoToggle, OnlyTheWatchSetFiresWhileMovingNoneWhenStoppedAndUtIsOredWhenOff) {
  SimFirmware fw(ROBUTER_SHIPPED_WORLDS "/empty.toml", seed_rule_config());
  ASSERT_TRUE(fw.ok()) << fw.error();
  SafetyMonitor mon;
  mon.attach(fw);
  const std::uint32_t all = emergency::kAllSensors;
  EXPECT_EQ(fired_sensors(fw), all) << "auto-toggle off, stopped: the default table (all 24)";

  // Auto-toggle on, stopped: nothing fires, every range reads 0.
  ASSERT_EQ(fw.ask("Uu1"), "ack");
  std::uint32_t f = fired_sensors(fw);
  std::printf("Uu1, stopped:         selection %s fired %s\n", sensor_list(selection(fw)).c_str(), sensor_list(f).c_str());
  EXPECT_EQ(selection(fw), 0u);
  EXPECT_EQ(f, 0u) << "fired " << sensor_list(f);
  for (int s = 1; s <= 24; ++s) EXPECT_EQ(fw.bb().ranges.reader().peek().mm[static_cast<std::size_t>(s - 1)], 0) << s;

  // Moving straight: the five of sensor 1 only (held first: the set has no data yet).
  ASSERT_EQ(fw.ask("AM 20 20"), "ack");
  ASSERT_TRUE(fw.run_until([&] { return commanded(fw).left == 20; }, 150)) << "granted once the set has read";
  f = fired_sensors(fw);
  std::printf("Uu1, AM 20 20:        selection %s fired %s\n", sensor_list(selection(fw)).c_str(), sensor_list(f).c_str());
  EXPECT_EQ(selection(fw), emergency::watch_mask(1));
  EXPECT_EQ(f, emergency::watch_mask(1)) << "fired " << sensor_list(f);

  // Rotating: the special set of sensor 7.
  fw.sim().robot().place(sim::Pose{3.0, 3.0, 0.0});
  ASSERT_EQ(fw.ask("AM 10 -10"), "ack");
  ASSERT_TRUE(fw.run_until([&] { return commanded(fw).left == 10; }, 150));
  f = fired_sensors(fw);
  std::printf("Uu1, AM 10 -10:       selection %s fired %s\n", sensor_list(selection(fw)).c_str(), sensor_list(f).c_str());
  EXPECT_EQ(selection(fw), emergency::watch_mask(7));
  EXPECT_EQ(f, emergency::watch_mask(7)) << "fired " << sensor_list(f);

  // UT while auto-toggle is on: stored, answered ack, not applied.
  const std::uint32_t rear = emergency::sensor_bit(13) | emergency::sensor_bit(12);
  ASSERT_EQ(fw.ask(ut(rear)), "ack");
  EXPECT_EQ(fw.bb().us_settings.reader().peek().user_table, rear) << "the table is stored";
  f = fired_sensors(fw);
  std::printf("Uu1, UT {12,13}:      selection %s fired %s\n", sensor_list(selection(fw)).c_str(), sensor_list(f).c_str());
  EXPECT_EQ(selection(fw), emergency::watch_mask(7)) << "not applied while auto-toggle is on";
  EXPECT_EQ(f, emergency::watch_mask(7)) << "fired " << sensor_list(f);

  // Auto-toggle off: the stored table OR the watch set.
  ASSERT_EQ(fw.ask("Uu0"), "ack");
  f = fired_sensors(fw);
  std::printf("Uu0, AM 10 -10:       selection %s fired %s\n", sensor_list(selection(fw)).c_str(), sensor_list(f).c_str());
  EXPECT_EQ(selection(fw), rear | emergency::watch_mask(7));
  EXPECT_EQ(f, rear | emergency::watch_mask(7)) << "fired " << sensor_list(f);

  // Stopped with auto-toggle off: the user table alone.
  ASSERT_EQ(fw.ask("AM 0 0"), "ack");
  f = fired_sensors(fw);
  std::printf("Uu0, stopped:         selection %s fired %s\n", sensor_list(selection(fw)).c_str(), sensor_list(f).c_str());
  EXPECT_EQ(selection(fw), rear);
  EXPECT_EQ(f, rear) << "fired " << sensor_list(f);

  // Auto-toggle back on while stopped: nothing fires again.
  ASSERT_EQ(fw.ask("Uu1"), "ack");
  f = fired_sensors(fw);
  std::printf("Uu1, stopped again:   selection %s fired %s\n", sensor_list(selection(fw)).c_str(), sensor_list(f).c_str());
  EXPECT_EQ(f, 0u) << "fired " << sensor_list(f);
  EXPECT_EQ(fw.bb().emergency.reader().peek().trips, 0u);
  EXPECT_EQ(mon.violations(), 0u) << mon.first_violation;
}

}  // namespace
}  // namespace robuter::test::safety_sim
