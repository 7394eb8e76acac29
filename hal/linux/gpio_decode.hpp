// SPDX-License-Identifier: GPL-3.0-or-later
// Pure encoding and decoding of the Linux GPIO v2 uAPI structures (no device needed).
#pragma once

#include <linux/gpio.h>

#include <cstdint>
#include <span>

namespace robuter::hal::gpio {

// What is asked of the chip: input lines with both edges reported.
struct LineRequest {
  std::span<const std::uint32_t> offsets;  // line offsets on the chip, in bit order
  bool active_low = true;                  // logical 1 = electrical low
  std::uint32_t debounce_us = 0;           // kernel debounce period, µs (0 = none)
  const char* consumer = "robuterd";       // label shown by gpioinfo
};

// Line state kept between polls: the level now and the lines seen active since last read.
struct EdgeState {
  std::uint32_t level = 0;        // bit i = line i active now
  std::uint32_t seen_active = 0;  // bit i = line i became active since its bit was last sampled
};

// Fills a GPIO_V2_GET_LINE_IOCTL request; false when there are no lines or more than 32.
bool build_request(const LineRequest& r, gpio_v2_line_request& out);
// The level mask of a GPIO_V2_LINE_GET_VALUES_IOCTL answer for `n` lines (request order).
std::uint32_t decode_values(const gpio_v2_line_values& v, std::size_t n);
// Applies one edge event (offsets as requested); false for an unknown line or event id.
bool apply_event(const gpio_v2_line_event& e, std::span<const std::uint32_t> offsets, EdgeState& s);
// Bits of `mask` active now or since the last sample of those bits; clears their latch.
std::uint32_t sample(EdgeState& s, std::uint32_t mask);

}  // namespace robuter::hal::gpio
