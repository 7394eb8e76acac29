// SPDX-License-Identifier: GPL-3.0-or-later
// The fields `<x> <y> <theta> <servo>` that BO, BV and the status stream's line each start with.
#pragma once

#include "protocol/codec/reply_writer.hpp"
#include "protocol/codec/robot_port.hpp"

namespace robuter::protocol {

// Appends " <x> <y> <theta> <servo>": the port's posture (0.1 mm, 0.01 degree) and servo (1 on, 0 off).
void posture_fields(const RobotPort& port, ReplyWriter& out) noexcept;

}  // namespace robuter::protocol
