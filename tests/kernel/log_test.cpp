// SPDX-License-Identifier: GPL-3.0-or-later
// The log ring: levels filter, records carry the tick, a full ring drops and counts.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "kernel/log.hpp"
#include "tests/support/log_capture.hpp"

namespace robuter {
namespace {

// Captures what flush() writes (tests/support/log_capture.hpp).
std::string drain_to_string() { return test::log_since_last(); }

TEST(Log, LevelsTicksAndDrops) {
  drain_to_string();  // records left by earlier tests in this process
  log::set_level(log::Level::info);
  log::set_tick(42);
  log::debug("hidden {}", 1);
  log::warn("range {} mm", 220);
  const auto out = drain_to_string();
  EXPECT_EQ(out, "[      42] warn  range 220 mm\n");
  for (int i = 0; i < 1000; ++i) log::info("flood {}", i);
  EXPECT_GT(log::dropped(), 0u);
  const auto flood = drain_to_string();
  EXPECT_NE(flood.find("records dropped"), std::string::npos);
  EXPECT_NE(flood.find("flood 0"), std::string::npos);
}

TEST(Log, LongMessagesAreCutNotOverflowed) {
  drain_to_string();
  log::set_level(log::Level::info);
  log::info("{}", std::string(1000, 'x'));
  const auto out = drain_to_string();
  EXPECT_LT(out.size(), 200u);
}

TEST(Log, LevelNamesParse) {
  EXPECT_EQ(from_word<log::Level>("warn"), log::Level::warn);
  EXPECT_EQ(from_word<log::Level>("loud"), std::nullopt);
  EXPECT_EQ(word(log::Level::error), "error");
}

}  // namespace
}  // namespace robuter
