// SPDX-License-Identifier: GPL-3.0-or-later
// The reply writer's formatting: integers with to_chars, checksum and terminator at the end.
#include "protocol/codec/reply_writer.hpp"

#include <charconv>
#include <cstring>

#include "protocol/codec/checksum.hpp"

namespace robuter::protocol {

// The session's format is frozen here so a mode change applies from the next reply on.
void ReplyWriter::begin() noexcept {
  finished_ = false;
  reset();
  started_ = false;
  verbose_ = session_->verbose_errors;
  checksums_ = session_->checksums;
  terminator_ = session_->terminator;
}

// Forgets the line in progress; a finished line stays until the next begin().
void ReplyWriter::reset() noexcept {
  if (finished_) return;
  length_ = 0;
  overflow_ = false;
}

// `ack` is the same in every session mode.
void ReplyWriter::ack() noexcept {
  reset();
  started_ = true;
  append("ack");
}

// Seed clients get the bare word; verbose sessions get the code and its reason.
void ReplyWriter::error(ErrorCode code) noexcept {
  reset();
  started_ = true;
  append("error");
  if (verbose_) {
    field(error_number(code));
    append(" ");
    append(error_name(code));
  }
}

// A data reply starts with its letter (or a fixed head).
void ReplyWriter::open(std::string_view head) noexcept {
  reset();
  started_ = true;
  append(head);
}

// Decimal via to_chars: no locale, no allocation.
void ReplyWriter::field(std::int64_t value) noexcept {
  char digits[24];
  const auto [end, ec] = std::to_chars(digits, digits + sizeof digits, value);
  if (ec != std::errc{}) {
    overflow_ = true;
    return;
  }
  append(" ");
  append(std::string_view(digits, static_cast<std::size_t>(end - digits)));
}

// One field per value, in order.
void ReplyWriter::fields(std::span<const std::int32_t> values) noexcept {
  for (const std::int32_t v : values) field(v);
}

void ReplyWriter::fields(std::initializer_list<std::int64_t> values) noexcept {
  for (const std::int64_t v : values) field(v);
}

// Port-supplied words must not break the line into tokens or lines.
void ReplyWriter::word(std::string_view text) noexcept {
  char clean[kMaxTokenLength];
  std::size_t n = 0;
  for (const char c : text) {
    if (n == kMaxTokenLength) break;
    const bool printable = c > ' ' && c < 0x7F && c != '*';
    clean[n++] = printable ? c : '_';
  }
  if (n == 0) clean[n++] = '-';
  append(" ");
  append(std::string_view(clean, n));
}

// Trusted fragments from the codec itself.
void ReplyWriter::raw(std::string_view text) noexcept { append(text); }

// All appends go through here so the bound is checked in one place.
void ReplyWriter::append(std::string_view text) noexcept {
  if (finished_ || overflow_ || text.size() > kBodyCapacity - length_) {
    overflow_ = true;
    return;
  }
  std::memcpy(buf_.data() + length_, text.data(), text.size());
  length_ += text.size();
}

// A missing or overflowed reply becomes an internal error, so every line gets one reply.
std::string_view ReplyWriter::finish() noexcept {
  if (finished_) return {buf_.data(), length_};
  if (!started_ || overflow_) error(ErrorCode::internal);
  finished_ = true;
  if (checksums_) {
    char hex[kChecksumDigits];
    format_checksum(crc16(body()), hex);
    buf_[length_++] = kChecksumMark;
    std::memcpy(buf_.data() + length_, hex, kChecksumDigits);
    length_ += kChecksumDigits;
  }
  const std::string_view term = terminator_bytes(terminator_);
  std::memcpy(buf_.data() + length_, term.data(), term.size());
  length_ += term.size();
  return {buf_.data(), length_};
}

}  // namespace robuter::protocol
