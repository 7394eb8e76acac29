// SPDX-License-Identifier: GPL-3.0-or-later
// A periodic process of the kernel and the row that schedules it.
#pragma once

#include <cstdint>

namespace robuter {

class Kernel;

// A module as the kernel sees it: start-up, one bounded activation, shut-down.
class Process {
 public:
  virtual ~Process() = default;
  // Start-up work (may allocate, open files); false aborts the start with the logged reason.
  virtual bool init(Kernel&) { return true; }
  // One activation: real-time code — no heap, no blocking I/O, no exceptions, bounded work.
  virtual void run(Kernel& k) = 0;
  // Shut-down work, called in reverse table order.
  virtual void close(Kernel&) {}
};

// One row of the process table (AP_Scheduler style: everything about a task on one line).
struct ProcessRow {
  const char* name = "";         // unique, short; used by config overrides and statistics
  Process* process = nullptr;    // the module object that runs
  std::uint32_t period = 1;      // activation period, ticks (≥ 1)
  std::uint32_t offset = 0;      // phase: first activation at this tick (< period)
  int priority = 0;              // within one tick, higher priority runs first
  std::uint32_t budget_us = 0;   // time budget per activation, µs (> 0)
};

}  // namespace robuter
