// SPDX-License-Identifier: GPL-3.0-or-later
// CPU time of the calling thread: what an activation costs, without the time others took the CPU.
#pragma once

#include <time.h>

#include <cstdint>

namespace robuter {

// The calling thread's CPU time, µs (CLOCK_THREAD_CPUTIME_ID): wall clock would also count the
// time other processes of a shared machine held the CPU.
inline std::int64_t thread_cpu_us() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000 + ts.tv_nsec / 1000;
}

}  // namespace robuter
