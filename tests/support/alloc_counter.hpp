// SPDX-License-Identifier: GPL-3.0-or-later
// Counts heap allocations made by the current thread while an AllocCounter is alive.
#pragma once

#include <cstdint>

namespace robuter::test {

// Arms counting on construction for this thread; count() is the allocations seen since.
class AllocCounter {
 public:
  AllocCounter();
  ~AllocCounter();
  std::uint64_t count() const;
  AllocCounter(const AllocCounter&) = delete;
  AllocCounter& operator=(const AllocCounter&) = delete;
};

}  // namespace robuter::test
