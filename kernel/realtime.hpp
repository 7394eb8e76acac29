// SPDX-License-Identifier: GPL-3.0-or-later
// Optional real-time set-up of the firmware process: SCHED_FIFO and locked memory.
#pragma once

#include "kernel/config.hpp"

namespace robuter {

// Applies what the configuration asks; where the system refuses, logs a clear warning with
// the reason and how to grant it, and carries on. Returns false if anything was refused.
bool apply_realtime(const KernelConfig& cfg);

}  // namespace robuter
