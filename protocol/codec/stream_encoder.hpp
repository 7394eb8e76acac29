// SPDX-License-Identifier: GPL-3.0-or-later
// The status line of the opt-in stream (XS): `@ <x> <y> <theta> <servo> <left> <right> <emerg> <clock>`.
#pragma once

#include <string_view>

#include "protocol/codec/reply_writer.hpp"
#include "protocol/codec/robot_port.hpp"

namespace robuter::protocol {

// The emergency field of a stream line: 0 clear, +1 motion held, +2 emergency latched, +4 protective stop.
int stream_emergency_field(const EmergencyStatus& status) noexcept;

// Builds one status line in `out` (session format: checksum, terminator) and returns it.
std::string_view encode_status_line(const RobotPort& port, ReplyWriter& out) noexcept;

}  // namespace robuter::protocol
