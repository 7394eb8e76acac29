// SPDX-License-Identifier: GPL-3.0-or-later
// The PTU-46 text protocol from the host's side: reply lines assembled from bytes, and parsed.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace robuter::ptu {

// Collects reply bytes into lines (CR or LF ends a line; empty lines are skipped). A line longer
// than the buffer, or one holding a byte that is not printable ASCII, is marked bad.
class ReplyAssembler {
 public:
  static constexpr std::size_t kCapacity = 80;  // longest line kept, characters

  // Feeds one byte; true when a line is complete (read it with line() / bad()).
  bool push(std::uint8_t b);
  std::string_view line() const { return {buf_.data(), len_}; }
  bool bad() const { return bad_done_; }
  // Forgets a partial line (after a time-out, so a late half-reply does not join the next).
  void clear();

 private:
  std::array<char, kCapacity> buf_{};  // the line being received
  std::size_t len_ = 0;                // characters in buf_
  bool bad_ = false;                   // the line being received is bad
  bool bad_done_ = false;              // the completed line was bad
  bool done_ = false;                  // the last push completed a line (buf_ is reset at the next)
};

// What a reply line says.
enum class ReplyKind : std::uint8_t {
  ok,       // "*" (possibly after echoed characters), with an optional number
  refused,  // "!" and the unit's message
  garbage,  // anything else
};
struct Reply {
  ReplyKind kind = ReplyKind::garbage;  // see ReplyKind
  std::optional<std::int32_t> number;   // the last integer after the '*' ("* -1755", "* Current Pan position is 12")
};
// Parses one line of the unit's replies (terse "* <n>" or verbose, echo on or off).
Reply parse_reply(std::string_view line);

// Writes "<text><n>\r" (n optional) into `out`; the length written (0 if it does not fit).
std::size_t format_command(char* out, std::size_t size, std::string_view text, std::optional<std::int32_t> n = {});

}  // namespace robuter::ptu
