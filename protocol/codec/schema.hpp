// SPDX-License-Identifier: GPL-3.0-or-later
// Parameter schemas of the command table: what a message's parameters must look like.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <string_view>

#include "protocol/codec/limits.hpp"

namespace robuter::protocol {

// The shapes of parameter lists the seed's messages use.
enum class SchemaKind : std::uint8_t {
  none,       // no parameter (BO, UN, ...)
  integers,   // exactly `count` decimal integers (AM, AC, UD, ...)
  one_of,     // one character from `choices` (ASN/ASF, Uu0/Uu1, USN/USS)
  table,      // 24 characters 0/1 (UT)
  text,       // the rest of the line, spaces included (AY)
};

// Inclusive bounds of one integer parameter, in the message's units.
struct IntRange {
  std::int32_t min = std::numeric_limits<std::int32_t>::min();  // smallest accepted value
  std::int32_t max = std::numeric_limits<std::int32_t>::max();  // largest accepted value
};

// One row's parameter schema.
struct Schema {
  SchemaKind kind = SchemaKind::none;              // shape
  std::uint8_t count = 0;                          // integers: how many
  std::array<IntRange, kMaxIntParams> ranges{};    // integers: bounds of each
  std::string_view choices{};                      // one_of: the accepted characters
  std::uint8_t min_count = 0;                      // integers: fewest accepted (0: exactly `count`)
  bool or_none = false;                            // integers: none at all is accepted too (XA)
};

// Schema builders so table rows read like the protocol's table.
constexpr Schema no_params() noexcept { return Schema{}; }
constexpr Schema integers(IntRange a) noexcept {
  return Schema{SchemaKind::integers, 1, {a, IntRange{}, IntRange{}}, {}};
}
constexpr Schema integers(IntRange a, IntRange b) noexcept {
  return Schema{SchemaKind::integers, 2, {a, b, IntRange{}}, {}};
}
constexpr Schema integers(IntRange a, IntRange b, IntRange c) noexcept {
  return Schema{SchemaKind::integers, 3, {a, b, c}, {}};
}
// The first `min` integers required, the rest optional (XG: x y, theta optional).
constexpr Schema integers_from(std::uint8_t min, IntRange a, IntRange b) noexcept {
  return Schema{SchemaKind::integers, 2, {a, b, IntRange{}}, {}, min};
}
constexpr Schema integers_from(std::uint8_t min, IntRange a, IntRange b, IntRange c) noexcept {
  return Schema{SchemaKind::integers, 3, {a, b, c}, {}, min};
}
// Either all `count` integers or none (XA: a pose, or none for a global search).
constexpr Schema integers_or_none(IntRange a, IntRange b, IntRange c) noexcept {
  return Schema{SchemaKind::integers, 3, {a, b, c}, {}, 0, true};
}
constexpr Schema one_of(std::string_view choices) noexcept {
  return Schema{SchemaKind::one_of, 0, {}, choices};
}
constexpr Schema sensor_table() noexcept { return Schema{SchemaKind::table, 0, {}, {}}; }
constexpr Schema rest_of_line() noexcept { return Schema{SchemaKind::text, 0, {}, {}}; }

}  // namespace robuter::protocol
