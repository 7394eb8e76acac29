// SPDX-License-Identifier: GPL-3.0-or-later
// The reply writer: builds exactly one reply line in a fixed buffer, in the session's format.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string_view>

#include "protocol/codec/error_code.hpp"
#include "protocol/codec/limits.hpp"
#include "protocol/codec/session.hpp"

namespace robuter::protocol {

// Holds one line at a time: begin(), then ack()/error()/open()+fields, then finish(). A later
// ack/error/open replaces what was written, so a handler can never emit two lines. Never
// allocates; an overflow turns the reply into `error` (internal).
class ReplyWriter {
 public:
  explicit ReplyWriter(SessionState& session) noexcept : session_(&session) {}

  // The session: handlers of X messages change it; the reply in progress is not affected.
  SessionState& session() noexcept { return *session_; }
  const SessionState& session() const noexcept { return *session_; }

  // Starts a new reply and freezes the session's format (terminator, checksum, verbosity).
  void begin() noexcept;
  // Replaces the reply by `ack`.
  void ack() noexcept;
  // Replaces the reply by `error` (or `error <n> <name>` when verbose errors are on).
  void error(ErrorCode code) noexcept;
  // Replaces the reply by a data reply starting with `head` (e.g. "S", "V robuterd").
  void open(std::string_view head) noexcept;
  // Appends " <value>" in decimal.
  void field(std::int64_t value) noexcept;
  // Appends " <values...>" in decimal.
  void fields(std::span<const std::int32_t> values) noexcept;
  // Appends " <value>" in decimal for each value, in order (a reply's numbers as listed).
  void fields(std::initializer_list<std::int64_t> values) noexcept;
  // Appends " <word>": at most kMaxTokenLength bytes, non-printables and spaces made '_'.
  void word(std::string_view text) noexcept;
  // Appends raw text with no leading space (already a valid reply fragment).
  void raw(std::string_view text) noexcept;

  // True once ack/error/open has been called since begin().
  bool has_reply() const noexcept { return started_; }
  // The reply so far, without checksum or terminator (for tests and the stream encoder).
  std::string_view body() const noexcept { return {buf_.data(), length_}; }
  // Ends the line (checksum if on, terminator) and returns it; valid until the next begin().
  // A second call returns the same line.
  std::string_view finish() noexcept;

 private:
  static constexpr std::size_t kTail = 1 + 4 + 2;  // '*' + 4 hex digits + CRLF
  static constexpr std::size_t kBodyCapacity = kReplyCapacity - kTail;

  void reset() noexcept;
  void append(std::string_view text) noexcept;

  SessionState* session_;                   // the link's session (not owned)
  std::array<char, kReplyCapacity> buf_{};  // the line being built
  std::size_t length_ = 0;                  // bytes used in buf_
  bool started_ = false;                    // a reply has been chosen
  bool overflow_ = false;                   // a field did not fit
  bool finished_ = false;                   // finish() has ended the line
  bool verbose_ = false;                    // session.verbose_errors at begin()
  bool checksums_ = false;                  // session.checksums at begin()
  Terminator terminator_ = Terminator::cr;  // session.terminator at begin()
};

}  // namespace robuter::protocol
