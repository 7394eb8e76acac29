// SPDX-License-Identifier: GPL-3.0-or-later
// Proves the whole firmware (simulator, link, ring, emergency, executor) allocates nothing in
// 10,000 steady-state ticks while a client talks to it.
#include <gtest/gtest.h>

#include "modules/firmware/sim_firmware.hpp"
#include "tests/support/alloc_counter.hpp"

namespace robuter {
namespace {

TEST(Firmware, TenThousandTicksOfTheWholeFirmwareAllocateNothing) {
#if defined(ROBUTER_SANITIZE)
  GTEST_SKIP() << "the sanitizers own malloc; this proof runs in the normal build";
#else
  test::SimFirmware fw;
  ASSERT_TRUE(fw.ok()) << fw.error();
  // Warm up every path once: motion, ring, stream, verbose errors, queries.
  for (const char* l : {"ASN", "AM 10 10", "XB1", "XS20", "BV", "XK", "XE", "Zz", "AM 0 0", "XB0"}) ASSERT_TRUE(fw.ask(l)) << l;
  fw.run_ticks(100);
  fw.count_lines();
  const std::string_view cycle[] = {"BO\r", "AM 10 -10\r", "BU\r", "BV\r", "UN\r",  "USN\r", "BC\r",
                                    "XE\r", "XK\r",        "AM 0 0\r", "Zz\r", "UT111111111111111111111111\r"};
  int replies = 0, stream = 0;
  test::AllocCounter counter;
  for (int i = 0; i < 10'000; ++i) {
    if (i % 10 == 0) fw.send_raw(cycle[(i / 10) % std::size(cycle)]);
    fw.step();
    const auto [r, s] = fw.count_lines();
    replies += r;
    stream += s;
  }
  const auto allocations = counter.count();
  EXPECT_EQ(allocations, 0u);
  EXPECT_EQ(replies, 1000);     // every request answered
  EXPECT_GE(stream, 490);       // the 20-tick status stream ran throughout
  EXPECT_GT(fw.bb().ranges.reader().peek().scans, 100u);  // the ring kept scanning
#endif
}

// Read-your-writes: commands pipelined with the queries that read them wait, line by line, for
// the emergency module and the executor (a fixed backlog per link) — still without allocating.
TEST(Firmware, PipelinedCommandsWaitingForTheirOwnersAllocateNothing) {
#if defined(ROBUTER_SANITIZE)
  GTEST_SKIP() << "the sanitizers own malloc; this proof runs in the normal build";
#else
  test::SimFirmware fw;
  ASSERT_TRUE(fw.ok()) << fw.error();
  const std::string_view batch = "ASN\rBO\rAC 0 0 0\rBO\rXE\rASF\rBO\rAM 0 0\r\x18XE\rXR\r";
  for (int i = 0; i < 5; ++i) {  // warm up
    fw.send_raw(batch);
    fw.run_ticks(100);
  }
  fw.count_lines();
  int replies = 0;
  test::AllocCounter counter;
  for (int i = 0; i < 2'000; ++i) {
    if (i % 100 == 0) fw.send_raw(batch);
    fw.step();
    replies += fw.count_lines().first;
  }
  EXPECT_EQ(counter.count(), 0u);
  EXPECT_EQ(replies, 20 * 10);  // every line answered
#endif
}

// New odometry frames at rest (AC, shifted and turned): the envelope carries the ring's obstacle
// evidence into each frame (EvidenceGrid::carry) from storage sized at start-up.
TEST(Firmware, OdometrySetsCarryingTheEvidenceAllocateNothing) {
#if defined(ROBUTER_SANITIZE)
  GTEST_SKIP() << "the sanitizers own malloc; this proof runs in the normal build";
#else
  test::SimFirmware fw;
  ASSERT_TRUE(fw.ok()) << fw.error();
  const std::string_view frames[] = {"AC 10000 0 0\r", "AC 0 0 0\r", "AC 0 5000 4500\r", "AC -3000 0 -9000\r"};
  for (const std::string_view f : frames) {  // warm up: the ring has seen the room, every frame once
    fw.send_raw(f);
    fw.run_ticks(200);
  }
  fw.count_lines();
  int replies = 0;
  test::AllocCounter counter;
  for (int i = 0; i < 4'000; ++i) {
    if (i % 100 == 0) fw.send_raw(frames[(i / 100) % std::size(frames)]);
    fw.step();
    replies += fw.count_lines().first;
  }
  EXPECT_EQ(counter.count(), 0u);
  EXPECT_EQ(replies, 40);  // every AC answered
  EXPECT_GT(fw.bb().ranges.reader().peek().scans, 10u);  // the ring kept scanning
#endif
}

}  // namespace
}  // namespace robuter
