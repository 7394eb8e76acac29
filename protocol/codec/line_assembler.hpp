// SPDX-License-Identifier: GPL-3.0-or-later
// Framing: turns received bytes into complete lines, framing errors and stop events.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "protocol/codec/error_code.hpp"
#include "protocol/codec/limits.hpp"

namespace robuter::protocol {

// What scanning the input produced.
struct FrameEvent {
  enum class Kind : std::uint8_t {
    none,   // the bytes were consumed without completing anything
    line,   // a complete, clean line (possibly empty): decode it
    error,  // a line was discarded: answer it with `error`
    stop,   // the immediate stop byte: stop the robot, write nothing
  };
  Kind kind = Kind::none;               // what happened
  std::string_view line{};              // line: its bytes without terminator, valid until next scan
  ErrorCode error = ErrorCode::none;    // error: why the line was discarded
};

// Byte-to-line framing with a fixed buffer (see docs/PROTOCOL.md "Framing"):
// * CR or LF ends a line; an LF right after a CR is ignored (so CRLF is one terminator).
// * Only printable ASCII (32..126) may appear in a line; any other byte (NUL, 0xFF, controls,
//   8-bit) makes the whole line one `error` (bad_byte) at its terminator.
// * A line longer than MAX_LENGTH bytes is discarded up to its terminator, then reported once
//   (line_too_long); framing stays in sync.
// * The stop byte 0x18 is taken out before framing and reported at once; it is never part of
//   a line and does not separate CR from LF. If it arrives in the middle of a line, that line
//   is cancelled: it is answered `error` (stopped) at its terminator and never executed.
class LineAssembler {
 public:
  static constexpr std::size_t MAX_LENGTH = kMaxLineLength;  // bytes before the terminator

  // Consumes bytes up to and including the first that completes an event; returns how many
  // were consumed and sets `event` (Kind::none when all were consumed without an event).
  std::size_t scan(std::span<const std::uint8_t> bytes, FrameEvent& event) noexcept;

  // Calls `sink(const FrameEvent&)` for every event in `bytes`, in order; no allocation.
  template <class Sink>
  void feed(std::span<const std::uint8_t> bytes, Sink&& sink) {
    while (!bytes.empty()) {
      FrameEvent event;
      const std::size_t used = scan(bytes, event);
      bytes = bytes.subspan(used);
      if (event.kind != FrameEvent::Kind::none) sink(static_cast<const FrameEvent&>(event));
    }
  }

  // Drops any partial line (e.g. when the link is reopened).
  void reset() noexcept;
  // True when `b`, fed next, would end a line (CR, or an LF that does not follow a CR).
  bool ends_line(std::uint8_t b) const noexcept { return b == 13 || (b == 10 && !after_cr_); }
  // Bytes of the unfinished line so far (saturates at MAX_LENGTH + 1).
  std::size_t pending() const noexcept { return count_; }

 private:
  // Ends the current line and fills `event`.
  void end_line(FrameEvent& event) noexcept;

  std::array<char, MAX_LENGTH> buf_{};  // the line being assembled
  std::size_t count_ = 0;               // bytes of the line so far, saturating at MAX_LENGTH + 1
  bool bad_byte_ = false;               // a non-printable byte is in the line
  bool stopped_ = false;                // a stop byte came in the middle of the line
  bool after_cr_ = false;               // the last line ended with CR: ignore one LF
};

}  // namespace robuter::protocol
