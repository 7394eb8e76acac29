// SPDX-License-Identifier: GPL-3.0-or-later
// Proves the three safety modules allocate nothing on the periodic path: every malloc of the
// kernel thread is counted over 10,000 ticks with motion, obstacles, holds, trips and re-enables.
#include <gtest/gtest.h>

#include <memory>

#include "kernel/log.hpp"
#include "tests/safety/rig.hpp"
#include "tests/support/alloc_counter.hpp"

namespace robuter::test {
namespace {

// Both obstacle rules: the envelope (default: grid, pose history, sweeps) and the seed's.
class NoAlloc : public testing::TestWithParam<const char*> {};

TEST_P(NoAlloc, TenThousandTicksOfTheSafetyCoreAllocateNothing) {
#if defined(ROBUTER_SANITIZE)
  GTEST_SKIP() << "the sanitizers own malloc; this proof runs in the normal build";
#else
  log::set_level(log::Level::debug);
  Config cfg;
  cfg.emergency.rule = GetParam();
  cfg.emergency.comm_limit_ticks = 500;
  auto r = std::make_unique<Rig>(cfg);
  ASSERT_TRUE(r->ok);
  r->step(100);  // warm-up: first scan

  std::uint64_t moving_ticks = 0;
  {
    test::AllocCounter counter;
    for (int i = 0; i < 10'000; ++i) {
      switch (i % 1000) {
        case 0: r->link.am(30, 30); break;
        case 150: r->ring.world[0] = 200; break;        // obstacle: trip
        case 200: r->ring.world[0] = 3000; r->link.xr(); break;
        case 250: r->link.uu(true); r->link.am(20, -20); break;  // hold, then resume
        case 400: r->link.aw(3000, 1000, 4500); break;  // go-to through the gate
        case 700: r->bumpers.state = 1; break;
        case 720: r->bumpers.state = 0; r->link.uu(false); r->link.xr(); break;
        case 800: r->link.stop_byte(); break;
        case 850: r->link.xr(); break;
        default: break;  // link silence past 500 ticks trips the comm watchdog
      }
      r->step();
      if (r->drive.moving()) ++moving_ticks;
    }
    EXPECT_EQ(counter.count(), 0u);
  }
  EXPECT_GT(moving_ticks, 1000u);
  EXPECT_GT(r->state().trips, 10u);
  EXPECT_EQ(r->drive.violations(), 0u) << r->drive.first_violation();
  log::flush();
#endif
}

INSTANTIATE_TEST_SUITE_P(Rules, NoAlloc, testing::Values("envelope", "seed"));

}  // namespace
}  // namespace robuter::test
