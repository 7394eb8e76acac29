// SPDX-License-Identifier: GPL-3.0-or-later
// GPIO v2 request building, value and edge-event decoding, pulse latching.
#include "hal/linux/gpio_decode.hpp"

#include <cstring>

namespace robuter::hal::gpio {

bool build_request(const LineRequest& r, gpio_v2_line_request& out) {
  if (r.offsets.empty() || r.offsets.size() > 32) return false;
  std::memset(&out, 0, sizeof out);
  for (std::size_t i = 0; i < r.offsets.size(); ++i) out.offsets[i] = r.offsets[i];
  std::strncpy(out.consumer, r.consumer, sizeof out.consumer - 1);
  out.num_lines = static_cast<std::uint32_t>(r.offsets.size());
  out.config.flags = GPIO_V2_LINE_FLAG_INPUT | GPIO_V2_LINE_FLAG_EDGE_RISING | GPIO_V2_LINE_FLAG_EDGE_FALLING;
  if (r.active_low) out.config.flags |= GPIO_V2_LINE_FLAG_ACTIVE_LOW;
  if (r.debounce_us > 0) {
    out.config.num_attrs = 1;
    out.config.attrs[0].attr.id = GPIO_V2_LINE_ATTR_ID_DEBOUNCE;
    out.config.attrs[0].attr.debounce_period_us = r.debounce_us;
    out.config.attrs[0].mask = r.offsets.size() == 64 ? ~0ULL : (1ULL << r.offsets.size()) - 1;
  }
  return true;
}

// Why no inversion here: with GPIO_V2_LINE_FLAG_ACTIVE_LOW the kernel reports logical values.
std::uint32_t decode_values(const gpio_v2_line_values& v, std::size_t n) {
  const std::uint64_t used = n >= 64 ? ~0ULL : (1ULL << n) - 1;
  return static_cast<std::uint32_t>(v.bits & v.mask & used);
}

// Edges are logical too (active-low applied): rising = became active.
bool apply_event(const gpio_v2_line_event& e, std::span<const std::uint32_t> offsets, EdgeState& s) {
  for (std::size_t i = 0; i < offsets.size() && i < 32; ++i) {
    if (offsets[i] != e.offset) continue;
    const std::uint32_t bit = 1U << i;
    if (e.id == GPIO_V2_LINE_EVENT_RISING_EDGE) {
      s.level |= bit;
      s.seen_active |= bit;
    } else if (e.id == GPIO_V2_LINE_EVENT_FALLING_EDGE) {
      s.level &= ~bit;
    } else {
      return false;
    }
    return true;
  }
  return false;
}

std::uint32_t sample(EdgeState& s, std::uint32_t mask) {
  const std::uint32_t out = (s.level | s.seen_active) & mask;
  s.seen_active &= ~mask;
  return out;
}

}  // namespace robuter::hal::gpio
