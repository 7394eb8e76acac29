// SPDX-License-Identifier: GPL-3.0-or-later
// Names of the error codes, as written in verbose error replies.
#include "protocol/codec/error_code.hpp"

#include "protocol/codec/vocabulary.hpp"

namespace robuter::protocol {

// One word per code so a verbose error stays three tokens: `error <n> <name>`.
std::string_view error_name(ErrorCode code) noexcept {
  switch (code) {
    case ErrorCode::none: return "none";
    case ErrorCode::unknown_command: return "unknown-command";
    case ErrorCode::bad_parameter_count: return "bad-parameter-count";
    case ErrorCode::not_a_number: return "not-a-number";
    case ErrorCode::out_of_range: return "out-of-range";
    case ErrorCode::line_too_long: return "line-too-long";
    case ErrorCode::bad_byte: return "bad-byte";
    case ErrorCode::refused_emergency: return "refused-emergency";
    case ErrorCode::not_permitted: return "not-permitted";
    case ErrorCode::line_too_short: return "line-too-short";
    case ErrorCode::bad_parameter: return "bad-parameter";
    case ErrorCode::bad_checksum: return "bad-checksum";
    case ErrorCode::unavailable: return "unavailable";
    case ErrorCode::busy: return "busy";
    case ErrorCode::stopped: return "stopped";
    case ErrorCode::internal: return "internal";
    case ErrorCode::no_unit: return word(ModeReason::no_unit);  // the word XD shows for the same fact
  }
  return "internal";
}

}  // namespace robuter::protocol
