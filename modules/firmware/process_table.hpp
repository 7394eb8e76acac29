// SPDX-License-Identifier: GPL-3.0-or-later
// The firmware's process table (the seed's kernel.c table), with configuration overrides.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "kernel/config.hpp"
#include "kernel/process.hpp"

namespace robuter {

// A row of the default table, before a module object is attached.
struct DefaultRow {
  const char* name;         // process and module name
  std::uint32_t period;     // ticks
  std::uint32_t offset;     // ticks
  int priority;             // higher runs first within a tick
  std::uint32_t budget_us;  // µs
};

// The defaults (seed 002's periods and offsets where the seed had the process).
std::span<const DefaultRow> default_table();

// A module object by name, as the firmware composed it.
struct NamedProcess {
  const char* name;
  Process* process;
};

// Builds the table: the default rows whose module is enabled and composed, with the configuration's
// overrides applied. Returns a message naming file, line and key on a bad override.
std::optional<std::string> build_table(const Config& cfg, std::span<const NamedProcess> modules,
                                       std::vector<ProcessRow>& out);

}  // namespace robuter
