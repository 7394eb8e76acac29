// SPDX-License-Identifier: GPL-3.0-or-later
// Decoding: one line of text → a typed command and its table row, or an error code.
#pragma once

#include <string_view>

#include "protocol/codec/command.hpp"
#include "protocol/codec/command_table.hpp"
#include "protocol/codec/error_code.hpp"

namespace robuter::protocol {

// The outcome of decoding a line: either error != none, or row and command are set.
struct Decoded {
  ErrorCode error = ErrorCode::none;  // why the line is not a command (none = it is)
  const CommandRow* row = nullptr;    // the command's row (set when error == none)
  Command command{};                  // its parameters (text views into the decoded line)
};

// Decodes a line without its terminator. Rules (docs/PROTOCOL.md "Decoding"): category and
// type are the first two characters, case-sensitive; parameters follow directly or after
// separators (' ' and ','), runs and leading/trailing separators are skipped; AY takes the
// rest of the line verbatim. Any byte value is safe to pass.
Decoded decode(std::string_view line) noexcept;

// Parses one whole decimal integer token with optional sign into `out`, checking `range`.
ErrorCode parse_integer(std::string_view token, IntRange range, std::int32_t& out) noexcept;

}  // namespace robuter::protocol
