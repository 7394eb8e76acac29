// SPDX-License-Identifier: GPL-3.0-or-later
// Proves the passage finder, the door crossing, the pan-tilt and the demonstration allocate
// nothing on the periodic path: a whole AG + Ad run through the 90 cm door, and a whole lap of the
// demonstration course (calibration included), with the allocation counter armed.
#include <gtest/gtest.h>

#include "modules/firmware/sim_firmware.hpp"
#include "tests/support/alloc_counter.hpp"

namespace robuter {
namespace {

TEST(CrossingNoAlloc, AWholeCrossingAllocatesNothing) {
#if defined(ROBUTER_SANITIZE)
  GTEST_SKIP() << "the sanitizers own malloc; this proof runs in the normal build";
#else
  test::SimFirmware fw(ROBUTER_WORLDS_DIR "/door90.toml", Config{}, {}, true);
  ASSERT_TRUE(fw.ok()) << fw.error();
  for (const char* l : {"XD", "BP", "AT", "Af"}) ASSERT_TRUE(fw.ask(l)) << l;  // warm the reply paths
  fw.run_ticks(100);
  fw.count_lines();
  auto gate = [&] { return fw.bb().gate_status.reader().peek().state; };
  auto doors = [&] { return fw.bb().doors_status.reader().peek().state; };
  test::AllocCounter counter;
  fw.send_raw("AG\r");
  for (int i = 0; i < 20'000 && gate() != ModeState::aligned && gate() != ModeState::failed; ++i) {
    fw.step();
    if (i % 500 == 0) fw.send_raw("XD\r");
    fw.count_lines();
  }
  ASSERT_EQ(gate(), ModeState::aligned);
  fw.send_raw("Ad\r");
  for (int i = 0; i < 30'000 && doors() != ModeState::crossed && doors() != ModeState::failed; ++i) {
    fw.step();
    if (i % 500 == 0) fw.send_raw("XD\r");
    fw.count_lines();
  }
  const auto allocations = counter.count();
  EXPECT_EQ(doors(), ModeState::crossed);
  EXPECT_EQ(allocations, 0u);
#endif
}

TEST(DemoNoAlloc, AWholeLapAllocatesNothing) {
#if defined(ROBUTER_SANITIZE)
  GTEST_SKIP() << "the sanitizers own malloc; this proof runs in the normal build";
#else
  Config cfg;
  cfg.demo.enabled = true;
  cfg.demo.laps = 1;
  test::SimFirmware fw(ROBUTER_WORLDS_DIR "/seed002_course.toml", cfg);
  ASSERT_TRUE(fw.ok()) << fw.error();
  ASSERT_TRUE(fw.ask("XD"));  // warm the reply path
  fw.count_lines();
  auto demo = [&] { return fw.bb().demo_status.reader().peek().state; };
  test::AllocCounter counter;
  for (int i = 0; i < 20'000 && demo() == ModeState::running; ++i) {
    fw.step();
    if (i % 500 == 0) fw.send_raw("XD\r");
    fw.count_lines();
  }
  const auto allocations = counter.count();
  EXPECT_EQ(demo(), ModeState::finished);
  EXPECT_EQ(allocations, 0u);
#endif
}

}  // namespace
}  // namespace robuter
