// SPDX-License-Identifier: GPL-3.0-or-later
// The kernel's parameters ([kernel]): tick, real-time set-up, log level.
#pragma once

#include <cstdint>
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
inline constexpr param::Param<KernelConfig> kKernelParams[] = {
    {"tick_us", &KernelConfig::tick_us, "µs", 100, 1'000'000, "",
     "tick length, µs (seed: 10 ms)"},
    {"realtime", &KernelConfig::realtime, "bool", 0, 0, "",
     "ask for SCHED_FIFO at start-up"},
    {"rt_priority", &KernelConfig::rt_priority, "", 1, 99, "",
     "SCHED_FIFO priority, 1..99"},
    {"lock_memory", &KernelConfig::lock_memory, "bool", 0, 0, "",
     "mlockall(MCL_CURRENT | MCL_FUTURE) at start-up"},
    {"log_level", &KernelConfig::log_level, "", 0, 0, "debug|info|warn|error|off",
     "debug, info, warn, error, off"},
};

}  // namespace robuter
