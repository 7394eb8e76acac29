// SPDX-License-Identifier: GPL-3.0-or-later
// One complete line in, exactly one reply line out: checksum, decode, dispatch, format.
#pragma once

#include <string_view>

#include "protocol/codec/error_code.hpp"
#include "protocol/codec/reply_writer.hpp"
#include "protocol/codec/robot_port.hpp"

namespace robuter::protocol {

// Handles one line (without terminator) and returns its reply line, terminator included;
// the view lives in `out` until its next begin(). Never throws, never allocates.
std::string_view handle_line(std::string_view line, RobotPort& port, ReplyWriter& out) noexcept;

// The reply for a line the framing discarded (too long, bad byte, stopped).
std::string_view reply_error(ErrorCode code, ReplyWriter& out) noexcept;

}  // namespace robuter::protocol
