// SPDX-License-Identifier: GPL-3.0-or-later
// GPIO v2 uAPI decoding with hand-filled structures, the line set over a fake line descriptor
// (a pipe carrying events), and the start-up error without a chip.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <vector>

#include "hal/linux/gpio_decode.hpp"
#include "hal/linux/gpio_lines.hpp"

namespace robuter {
namespace {

using hal::gpio::EdgeState;

gpio_v2_line_event event(std::uint32_t offset, std::uint32_t id, std::uint32_t seq = 1) {
  gpio_v2_line_event e{};
  e.timestamp_ns = 1'000'000ULL * seq;
  e.id = id;
  e.offset = offset;
  e.seqno = seq;
  e.line_seqno = seq;
  return e;
}

TEST(GpioDecode, RequestAsksForInputsWithBothEdges) {
  const std::uint32_t offsets[] = {17, 27, 5};
  gpio_v2_line_request r{};
  ASSERT_TRUE(hal::gpio::build_request({offsets, true, 0, "robuterd"}, r));
  EXPECT_EQ(r.num_lines, 3u);
  EXPECT_EQ(r.offsets[0], 17u);
  EXPECT_EQ(r.offsets[1], 27u);
  EXPECT_EQ(r.offsets[2], 5u);
  EXPECT_STREQ(r.consumer, "robuterd");
  EXPECT_EQ(r.config.flags, GPIO_V2_LINE_FLAG_INPUT | GPIO_V2_LINE_FLAG_EDGE_RISING | GPIO_V2_LINE_FLAG_EDGE_FALLING |
                                GPIO_V2_LINE_FLAG_ACTIVE_LOW);
  EXPECT_EQ(r.config.num_attrs, 0u);

  ASSERT_TRUE(hal::gpio::build_request({offsets, false, 5000, "robuterd"}, r));
  EXPECT_EQ(r.config.flags & GPIO_V2_LINE_FLAG_ACTIVE_LOW, 0u);
  ASSERT_EQ(r.config.num_attrs, 1u);
  EXPECT_EQ(r.config.attrs[0].attr.id, static_cast<std::uint32_t>(GPIO_V2_LINE_ATTR_ID_DEBOUNCE));
  EXPECT_EQ(r.config.attrs[0].attr.debounce_period_us, 5000u);
  EXPECT_EQ(r.config.attrs[0].mask, 0b111u);  // every requested line

  EXPECT_FALSE(hal::gpio::build_request({{}, true, 0, "robuterd"}, r));
  std::vector<std::uint32_t> many(33, 0);
  for (std::size_t i = 0; i < many.size(); ++i) many[i] = static_cast<std::uint32_t>(i);
  EXPECT_FALSE(hal::gpio::build_request({many, true, 0, "robuterd"}, r));
}

TEST(GpioDecode, ValuesAreMaskedToTheRequestedLines) {
  gpio_v2_line_values v{};
  v.bits = 0b1101;
  v.mask = 0b0111;
  EXPECT_EQ(hal::gpio::decode_values(v, 3), 0b101u);
  v.mask = ~0ULL;
  EXPECT_EQ(hal::gpio::decode_values(v, 2), 0b01u);
}

TEST(GpioDecode, EdgesSetAndClearTheirLine) {
  const std::uint32_t offsets[] = {17, 27};
  EdgeState s;
  EXPECT_TRUE(hal::gpio::apply_event(event(27, GPIO_V2_LINE_EVENT_RISING_EDGE), offsets, s));
  EXPECT_EQ(s.level, 0b10u);
  EXPECT_TRUE(hal::gpio::apply_event(event(17, GPIO_V2_LINE_EVENT_RISING_EDGE), offsets, s));
  EXPECT_EQ(s.level, 0b11u);
  EXPECT_TRUE(hal::gpio::apply_event(event(27, GPIO_V2_LINE_EVENT_FALLING_EDGE), offsets, s));
  EXPECT_EQ(s.level, 0b01u);
  EXPECT_FALSE(hal::gpio::apply_event(event(4, GPIO_V2_LINE_EVENT_RISING_EDGE), offsets, s));  // not ours
  EXPECT_FALSE(hal::gpio::apply_event(event(17, 9), offsets, s));                            // no such edge
  EXPECT_EQ(s.level, 0b01u);
}

// A contact closed and opened between two samples reads pressed exactly once.
TEST(GpioDecode, AShortPulseIsSampledOnce) {
  const std::uint32_t offsets[] = {17, 27};
  EdgeState s;
  hal::gpio::apply_event(event(17, GPIO_V2_LINE_EVENT_RISING_EDGE), offsets, s);
  hal::gpio::apply_event(event(17, GPIO_V2_LINE_EVENT_FALLING_EDGE), offsets, s);
  EXPECT_EQ(s.level, 0u);
  EXPECT_EQ(hal::gpio::sample(s, 0b10), 0u);   // another line's latch is not consumed
  EXPECT_EQ(hal::gpio::sample(s, 0b01), 1u);
  EXPECT_EQ(hal::gpio::sample(s, 0b01), 0u);
}

// The line set over a pipe standing in for the line request's descriptor: bumpers are the
// first lines, inputs the rest; reading never blocks.
TEST(GpioLines, EventsFromTheLineDescriptor) {
  int p[2];
  ASSERT_EQ(::pipe(p), 0);
  hal::GpioLines lines(p[0], {17, 27}, {5});
  EXPECT_FALSE(lines.error());
  EXPECT_EQ(lines.count(), 1u);
  EXPECT_EQ(lines.pressed(), 0u);  // nothing queued: no blocking
  const gpio_v2_line_event ev[] = {event(27, GPIO_V2_LINE_EVENT_RISING_EDGE, 1),
                                   event(5, GPIO_V2_LINE_EVENT_RISING_EDGE, 2)};
  ASSERT_EQ(::write(p[1], ev, sizeof ev), static_cast<ssize_t>(sizeof ev));
  EXPECT_EQ(lines.pressed(), 0b10u);
  EXPECT_EQ(lines.levels(), 0b1u);
  const gpio_v2_line_event up[] = {event(27, GPIO_V2_LINE_EVENT_FALLING_EDGE, 3),
                                   event(99, GPIO_V2_LINE_EVENT_RISING_EDGE, 4)};
  ASSERT_EQ(::write(p[1], up, sizeof up), static_cast<ssize_t>(sizeof up));
  EXPECT_EQ(lines.pressed(), 0u);
  EXPECT_EQ(lines.bad_events(), 1u);  // offset 99 is not requested
  ::close(p[1]);
}

// This machine has no GPIO chip: start-up fails naming the chip.
TEST(GpioLines, MissingChipIsNamed) {
  hal::GpioLines lines("/dev/gpiochip-robuter-test", {17}, {}, true, 0);
  ASSERT_TRUE(lines.error());
  EXPECT_NE(lines.error()->find("/dev/gpiochip-robuter-test"), std::string::npos) << *lines.error();
  EXPECT_NE(lines.error()->find("No such file"), std::string::npos) << *lines.error();
  EXPECT_EQ(lines.pressed(), 0u);  // unusable, but harmless
}

TEST(GpioLines, NoLinesIsAnError) {
  hal::GpioLines lines("/dev/gpiochip0", {}, {}, true, 0);
  ASSERT_TRUE(lines.error());
  EXPECT_NE(lines.error()->find("/dev/gpiochip0"), std::string::npos) << *lines.error();
}

}  // namespace
}  // namespace robuter
