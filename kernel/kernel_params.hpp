// SPDX-License-Identifier: GPL-3.0-or-later
// The kernel's parameters ([kernel]): tick, real-time set-up, log level.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/param.hpp"

namespace robuter {

// Kernel timing and real-time set-up.
struct KernelConfig {
  std::uint32_t tick_us = 10'000;   // tick length, µs (seed: 10 ms)
  bool realtime = false;            // ask for SCHED_FIFO at start-up
  int rt_priority = 50;             // SCHED_FIFO priority, 1..99
  bool lock_memory = false;         // mlockall(MCL_CURRENT | MCL_FUTURE) at start-up
  std::string log_level = "info";   // debug, info, warn, error, off
};

// [kernel]: each key, its unit, range and doc (the default is the field's initialiser).
std::span<const param::Param<KernelConfig>> kernel_params();

}  // namespace robuter
