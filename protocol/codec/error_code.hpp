// SPDX-License-Identifier: GPL-3.0-or-later
// Why a line was answered `error`: the codes and names shown by verbose errors (XB1).
#pragma once

#include <cstdint>
#include <string_view>

namespace robuter::protocol {

// Stable numbers: clients may match on them, so never renumber, only append.
enum class ErrorCode : std::uint8_t {
  none = 0,                  // no error
  unknown_command = 1,       // category/type not in the command table
  bad_parameter_count = 2,   // missing or extra parameters
  not_a_number = 3,          // an integer parameter is not a whole decimal integer
  out_of_range = 4,          // a value outside the message's range
  line_too_long = 5,         // more than kMaxLineLength bytes before the terminator
  bad_byte = 6,              // a byte outside printable ASCII (NUL, 0xFF, controls) in the line
  refused_emergency = 7,     // the emergency module refused the request
  not_permitted = 8,         // disabled by configuration (pass-through, ...)
  line_too_short = 9,        // fewer than two characters before the terminator
  bad_parameter = 10,        // a parameter of the wrong shape (choice, sensor table)
  bad_checksum = 11,         // checksums are on and the line's is absent or wrong
  unavailable = 12,          // the equipment or module is not fitted or not running
  busy = 13,                 // the robot is doing something that excludes the request
  stopped = 14,              // a stop byte arrived in the middle of the line
  internal = 15,             // the reply could not be built (a bug)
  no_unit = 16,              // Ap, AG, Ad: no pan-tilt unit to scan with (none fitted, or its module absent)
};

// The hyphenated reason word of a code, as written after its number.
std::string_view error_name(ErrorCode code) noexcept;

// The number written for a code in verbose errors.
constexpr int error_number(ErrorCode code) noexcept { return static_cast<int>(code); }

}  // namespace robuter::protocol
