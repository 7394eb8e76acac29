// SPDX-License-Identifier: GPL-3.0-or-later
// Per-process execution statistics and the tick lateness histogram.
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>

#include "kernel/clock.hpp"

namespace robuter {

// What the kernel measured of one process since start-up.
struct ProcessStats {
  std::uint64_t activations = 0;        // all runs (periodic and descriptor-driven)
  std::uint64_t event_activations = 0;  // runs caused by a readable descriptor or a trigger
  Nanos total_ns = 0;                   // summed execution time, ns
  Nanos max_ns = 0;                     // longest execution, ns
  std::uint64_t overruns = 0;           // runs longer than the time budget
  std::uint64_t slips = 0;              // periodic runs started a period or more late

  // Mean execution time, ns (0 before the first run).
  Nanos mean_ns() const { return activations ? total_ns / static_cast<Nanos>(activations) : 0; }
  // Adds one execution of `ns` against `budget_ns`.
  void record(Nanos ns, Nanos budget_ns) {
    ++activations;
    total_ns += ns;
    if (ns > max_ns) max_ns = ns;
    if (ns > budget_ns) ++overruns;
  }
};

// Distribution of how late each tick started, µs: 1 µs bins to 1 ms, 100 µs bins to 100 ms.
class LatenessHistogram {
 public:
  static constexpr int kFineBins = 1000;    // 0..999 µs, 1 µs each
  static constexpr int kCoarseBins = 990;   // 1 ms..99.9 ms, 100 µs each
  // Records one tick's lateness in ns (negative counts as 0).
  void record(Nanos late_ns);
  // The lateness at quantile q in [0,1], µs (upper edge of its bin).
  double quantile_us(double q) const;
  double max_us() const { return static_cast<double>(max_ns_) / 1000.0; }
  double mean_us() const;
  std::uint64_t count() const { return count_; }

 private:
  std::array<std::uint64_t, kFineBins + kCoarseBins + 1> bins_{};  // last bin: ≥ 100 ms
  std::uint64_t count_ = 0;   // ticks recorded
  Nanos max_ns_ = 0;          // largest lateness, ns
  Nanos total_ns_ = 0;        // summed lateness, ns
};

}  // namespace robuter
