// SPDX-License-Identifier: GPL-3.0-or-later
// The process's own memory figures, as the kernel counts them (/proc/self/status).
#pragma once

#include <cstdint>
#include <optional>

namespace robuter {

// Why: `--stats` and the memory test report the peak resident set (VmHWM, kB); empty where the
// system does not say (no /proc).
std::optional<std::uint64_t> peak_rss_kb();

}  // namespace robuter
