// SPDX-License-Identifier: GPL-3.0-or-later
// A decoded command: its id and its parameters, ready for a handler.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "protocol/codec/command_id.hpp"
#include "protocol/codec/limits.hpp"
#include "protocol/codec/port_types.hpp"

namespace robuter::protocol {

// Only the fields the row's schema names are meaningful.
struct Command {
  CommandId id = CommandId::none;                    // which command
  std::array<std::int32_t, kMaxIntParams> ints{};    // integer parameters, in the message's units
  std::uint8_t int_count = 0;                        // how many of `ints` were given
  char choice = 0;                                   // the character of a one-of parameter
  SensorTable table{};                               // UT: bit k = sensor k+1 active
  std::string_view text{};                           // AY: rest of the line; valid while handled
};

}  // namespace robuter::protocol
