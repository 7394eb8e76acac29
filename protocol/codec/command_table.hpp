// SPDX-License-Identifier: GPL-3.0-or-later
// The one command table: (category, type) → command id, parameter schema and handler.
#pragma once

#include <span>
#include <string_view>

#include "protocol/codec/command.hpp"
#include "protocol/codec/command_id.hpp"
#include "protocol/codec/schema.hpp"

namespace robuter::protocol {

class RobotPort;
class ReplyWriter;

// Every handler writes exactly one reply through the writer (the writer enforces it).
using Handler = void (*)(const Command& command, RobotPort& port, ReplyWriter& out);

// One message of the protocol; adding a message is adding one row.
struct CommandRow {
  char category;             // first character, case-sensitive ('A', 'B', 'U', 'X')
  char type;                 // second character, case-sensitive
  CommandId id;              // the command's identifier
  Schema schema;             // what its parameters must look like
  Handler handler;           // what it does and replies
  std::string_view summary;  // one line for docs and tools
};

// All rows, in the table's order.
std::span<const CommandRow> command_table() noexcept;

// The row for a category/type pair, or nullptr.
const CommandRow* find_command(char category, char type) noexcept;

}  // namespace robuter::protocol
