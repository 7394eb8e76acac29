// SPDX-License-Identifier: GPL-3.0-or-later
// Every message robuterd knows and robuterctl's own words: for `help`, completion and pairing.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace robuter::ctl {

struct CommandHelp {
  std::string_view name;     // what completion offers (`AM`, `XC1`, `help`)
  std::string_view syntax;   // how it is written, with its parameters
  std::string_view reply;    // what robuterd answers (empty for local words)
  std::string_view summary;  // what it does, one line
  bool local = false;        // handled by robuterctl, never sent
};

// The table, seed messages first (docs/PROTOCOL.md §4–§6), then the extensions (§8), then the
// console's own words.
std::span<const CommandHelp> command_table();

// `help` alone: one line per entry; `help WORD`: the entries whose name starts with WORD
// (`help XC` shows XC0 and XC1); an unknown word says so.
std::string help_text(std::string_view word);

}  // namespace robuter::ctl
