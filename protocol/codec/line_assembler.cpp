// SPDX-License-Identifier: GPL-3.0-or-later
// Framing of the command link: terminators, length bound, bad bytes and the stop byte.
#include "protocol/codec/line_assembler.hpp"

namespace robuter::protocol {
namespace {

constexpr std::uint8_t kCR = 13;
constexpr std::uint8_t kLF = 10;

// Printable ASCII is the only thing a protocol line may contain.
constexpr bool printable(std::uint8_t b) noexcept { return b >= 0x20 && b <= 0x7E; }

}  // namespace

// One pass over the bytes; returns at the first event so the caller can act on it in order.
std::size_t LineAssembler::scan(std::span<const std::uint8_t> bytes, FrameEvent& event) noexcept {
  event = FrameEvent{};
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    const std::uint8_t b = bytes[i];
    if (b == kStopByte) {  // out of band: does not touch after_cr_ or the line's bytes
      if (count_ > 0) stopped_ = true;
      event.kind = FrameEvent::Kind::stop;
      return i + 1;
    }
    if (b == kLF && after_cr_) {
      after_cr_ = false;
      continue;
    }
    after_cr_ = false;
    if (b == kCR || b == kLF) {
      after_cr_ = (b == kCR);
      end_line(event);
      return i + 1;
    }
    if (count_ < MAX_LENGTH) buf_[count_] = static_cast<char>(b);
    if (count_ <= MAX_LENGTH) ++count_;
    if (!printable(b)) bad_byte_ = true;
  }
  return bytes.size();
}

// The first defect found decides the error; a clean line is handed over as a view of buf_.
void LineAssembler::end_line(FrameEvent& event) noexcept {
  if (count_ > MAX_LENGTH) {
    event.kind = FrameEvent::Kind::error;
    event.error = ErrorCode::line_too_long;
  } else if (bad_byte_) {
    event.kind = FrameEvent::Kind::error;
    event.error = ErrorCode::bad_byte;
  } else if (stopped_) {
    event.kind = FrameEvent::Kind::error;
    event.error = ErrorCode::stopped;
  } else {
    event.kind = FrameEvent::Kind::line;
    event.line = std::string_view(buf_.data(), count_);
  }
  count_ = 0;
  bad_byte_ = false;
  stopped_ = false;
}

// Back to the state of a fresh link.
void LineAssembler::reset() noexcept {
  count_ = 0;
  bad_byte_ = false;
  stopped_ = false;
  after_cr_ = false;
}

}  // namespace robuter::protocol
