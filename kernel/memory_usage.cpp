// SPDX-License-Identifier: GPL-3.0-or-later
// Reads VmHWM from /proc/self/status (start-up and exit only: never on the periodic path).
#include "kernel/memory_usage.hpp"

#include <cstdio>
#include <cstring>

namespace robuter {

std::optional<std::uint64_t> peak_rss_kb() {
  std::FILE* f = std::fopen("/proc/self/status", "r");
  if (f == nullptr) return std::nullopt;
  char line[256];
  std::optional<std::uint64_t> kb;
  while (std::fgets(line, sizeof line, f) != nullptr) {
    unsigned long long v = 0;
    if (std::strncmp(line, "VmHWM:", 6) == 0 && std::sscanf(line + 6, "%llu", &v) == 1) {
      kb = v;
      break;
    }
  }
  std::fclose(f);
  return kb;
}

}  // namespace robuter
