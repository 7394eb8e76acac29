// SPDX-License-Identifier: GPL-3.0-or-later
// The kernel's parameters ([kernel]): tick, real-time set-up, log level: the table (compiled once, not in every includer of the configuration).
#include "kernel/kernel_params.hpp"

namespace robuter {

namespace {
constexpr param::Param<KernelConfig> kKernelParams[] = {
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
}  // namespace

std::span<const param::Param<KernelConfig>> kernel_params() { return kKernelParams; }

}  // namespace robuter
