// SPDX-License-Identifier: GPL-3.0-or-later
// Proves the pan-tilt path allocates nothing: 10,000 ticks of the whole firmware scanning with the
// emulated unit (on its pty, and wired in-process) while a client reads BP, BF, BD and XD, then
// the unit unplugged and detected.
#include <gtest/gtest.h>

#include "modules/firmware/sim_firmware.hpp"
#include "tests/support/alloc_counter.hpp"

namespace robuter {
namespace {

// `on_pty`: the unit on its own pty (--ptu-pty/--ptu-port); otherwise wired in-process (the
// default of --sim).
void scanning_and_unplugging_allocate_nothing(bool on_pty) {
  test::SimFirmware fw(ROBUTER_WORLDS_DIR "/door90.toml", Config{}, {}, on_pty);
  ASSERT_TRUE(fw.ok()) << fw.error();
  for (const char* l : {"Ap", "BP", "BF", "BD", "XD"}) ASSERT_TRUE(fw.ask(l)) << l;
  fw.run_ticks(500);
  fw.count_lines();
  const std::string_view cycle[] = {"BP\r", "BF\r", "BD\r", "XD\r"};
  int replies = 0;
  const std::uint32_t readings = fw.bb().pan_tilt_scan.reader().peek().readings;
  test::AllocCounter counter;
  for (int i = 0; i < 10'000; ++i) {
    if (i % 10 == 0) fw.send_raw(cycle[(i / 10) % std::size(cycle)]);
    fw.step();
    replies += fw.count_lines().first;
  }
  fw.unplug_ptu();
  fw.run_ticks(100);
  const auto allocations = counter.count();
  EXPECT_EQ(allocations, 0u);
  EXPECT_EQ(replies, 1000);
  EXPECT_GT(fw.bb().pan_tilt_scan.reader().peek().readings, readings + 1000);  // ~100 s of sweeping
  EXPECT_EQ(fw.bb().pan_tilt_status.reader().peek().state, ModeState::failed);
}

TEST(PtuNoAlloc, ScanningAndUnpluggingAllocateNothing) {
#if defined(ROBUTER_SANITIZE)
  GTEST_SKIP() << "the sanitizers own malloc; this proof runs in the normal build";
#else
  scanning_and_unplugging_allocate_nothing(true);
#endif
}

TEST(PtuNoAlloc, InProcessUnitAllocatesNothing) {
#if defined(ROBUTER_SANITIZE)
  GTEST_SKIP() << "the sanitizers own malloc; this proof runs in the normal build";
#else
  scanning_and_unplugging_allocate_nothing(false);
#endif
}

}  // namespace
}  // namespace robuter
