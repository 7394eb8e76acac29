// SPDX-License-Identifier: GPL-3.0-or-later
// Levelled log stamped with the kernel tick; the periodic path only formats into a fixed ring.
#pragma once

#include <fmt/format.h>

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <string_view>

#include "kernel/vocabulary.hpp"

namespace robuter::log {

// The levels, least severe first, with their words (the command line, [kernel] log_level, records):
// `from_word<Level>("warn")`, `word(Level::warn)`.
#define ROBUTER_LOG_LEVELS(X) X(debug, "debug") X(info, "info") X(warn, "warn") X(error, "error") X(off, "off")
enum class Level : std::uint8_t { ROBUTER_LOG_LEVELS(ROBUTER_VOCAB_ENUMERATOR) };
ROBUTER_VOCABULARY(Level, ROBUTER_LOG_LEVELS, "off");

// Minimum level that is recorded (others cost one comparison).
void set_level(Level l);
Level level();
// The tick written on every record (the kernel sets it each tick).
void set_tick(std::uint64_t tick);
// Starts the drain thread that writes records to `sink` (stderr by default).
void start(std::FILE* sink = stderr);
// Stops the drain thread after writing every record left.
void stop();
// Writes every pending record now, from the calling thread (tests, start-up errors).
void flush();
// Records that could not be queued because the ring was full.
std::uint64_t dropped();

namespace detail {
constexpr std::size_t kMessageBytes = 160;  // longest message kept, bytes (longer is cut)
// Reserves a ring slot, formats into it and publishes it; never allocates or blocks.
void push(Level l, const char* text, std::size_t len);
}  // namespace detail

// Formats a record; the arguments are formatted into a stack buffer, never the heap.
template <typename... Args>
void write(Level l, fmt::format_string<Args...> f, Args&&... args) {
  if (l < level()) return;
  char buf[detail::kMessageBytes];
  const auto r = fmt::format_to_n(buf, sizeof buf, f, std::forward<Args>(args)...);
  detail::push(l, buf, r.size < sizeof buf ? r.size : sizeof buf);
}

template <typename... Args> void debug(fmt::format_string<Args...> f, Args&&... a) { write(Level::debug, f, std::forward<Args>(a)...); }
template <typename... Args> void info(fmt::format_string<Args...> f, Args&&... a) { write(Level::info, f, std::forward<Args>(a)...); }
template <typename... Args> void warn(fmt::format_string<Args...> f, Args&&... a) { write(Level::warn, f, std::forward<Args>(a)...); }
template <typename... Args> void error(fmt::format_string<Args...> f, Args&&... a) { write(Level::error, f, std::forward<Args>(a)...); }

}  // namespace robuter::log
