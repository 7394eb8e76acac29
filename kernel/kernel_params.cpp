// SPDX-License-Identifier: GPL-3.0-or-later
// The kernel's parameters ([kernel]): tick, real-time set-up, log level: the table (compiled once, not in every includer of the configuration).
#include "kernel/kernel_params.hpp"

#include "kernel/log.hpp"

namespace robuter {

std::span<const param::Param<KernelConfig>> kernel_params() {
  using P = param::Param<KernelConfig>;
  static constexpr P kRows[] = {
      P::integer("tick_us", &KernelConfig::tick_us, "µs", 100, 1'000'000, "tick length, µs (seed: 10 ms)"),
      P::flag("realtime", &KernelConfig::realtime, "ask for SCHED_FIFO at start-up"),
      P::integer("rt_priority", &KernelConfig::rt_priority, "", 1, 99, "SCHED_FIFO priority, 1..99"),
      P::flag("lock_memory", &KernelConfig::lock_memory, "mlockall(MCL_CURRENT | MCL_FUTURE) at start-up"),
      P::word("log_level", &KernelConfig::log_level, word_list<log::Level>(), "debug, info, warn, error, off"),
  };
  return kRows;
}

}  // namespace robuter
