// SPDX-License-Identifier: GPL-3.0-or-later
// A module's parameter table (ArduPilot's AP_Param var_info): each module declares the keys of its
// configuration section — field, unit, range, one-line doc; the default is the field's initialiser —
// and the kernel's configuration reader only binds and checks them (kernel/config.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace robuter::param {

// The largest value of a 32-bit unsigned key.
inline constexpr long long kU32 = std::numeric_limits<std::uint32_t>::max();

// The field a key sets, by its type: an integer (bounded by lo..hi), a boolean, a string (one of
// `choices` when given), a list of strings, a list of integers (each within lo..hi).
template <typename S>
using Field = std::variant<std::uint32_t S::*, std::int32_t S::*, std::uint64_t S::*, bool S::*, std::string S::*,
                           std::vector<std::string> S::*, std::vector<std::uint32_t> S::*>;

// One key of a section.
template <typename S>
struct Param {
  std::string_view key;      // key within its section, e.g. "timeout_ms" of [sonar]
  Field<S> field;            // the struct field it sets (its initialiser is the default)
  std::string_view unit;     // unit as docs/CONFIG.md writes it ("mm", "cm/s", "bool"; "" none)
  long long lo = 0;          // integers: smallest value accepted
  long long hi = 0;          // integers: largest value accepted
  std::string_view choices;  // strings: the words accepted, '|'-separated ("" = any text)
  std::string_view doc;      // what it does, one line

  // The rows of a table, one constructor per kind (a table reads one key per line):
  // a boolean key (unit "bool");
  static constexpr Param flag(std::string_view key, bool S::*f, std::string_view doc) {
    return {key, f, "bool", 0, 0, "", doc};
  }
  // an integer, or a list of integers, each within lo..hi;
  static constexpr Param integer(std::string_view key, Field<S> f, std::string_view unit, long long lo, long long hi,
                                 std::string_view doc) {
    return {key, f, unit, lo, hi, "", doc};
  }
  // a word, one of `choices` ('|'-separated);
  static constexpr Param word(std::string_view key, std::string S::*f, std::string_view choices, std::string_view doc) {
    return {key, f, "", 0, 0, choices, doc};
  }
  // any text, or a list of texts (a path, a name, command prefixes).
  static constexpr Param text(std::string_view key, Field<S> f, std::string_view unit, std::string_view doc) {
    return {key, f, unit, 0, 0, "", doc};
  }
};

// One table of two: rows shared by several sections (a serial port's keys) followed by a
// section's own.
template <typename S, std::size_t A, std::size_t B>
constexpr std::array<Param<S>, A + B> join(const std::array<Param<S>, A>& a, const std::array<Param<S>, B>& b) {
  std::array<Param<S>, A + B> out{};
  for (std::size_t i = 0; i < A; ++i) out[i] = a[i];
  for (std::size_t i = 0; i < B; ++i) out[A + i] = b[i];
  return out;
}

}  // namespace robuter::param
