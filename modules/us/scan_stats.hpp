// SPDX-License-Identifier: GPL-3.0-or-later
// Running means of the ring's node and full-scan read times (USN, USS).
#pragma once

#include <cstdint>

namespace robuter::us {

// Sums and counts since start; the means are what USN and USS report.
struct ScanStats {
  std::uint64_t node_ticks = 0;   // sum of node read times, ticks
  std::uint64_t nodes = 0;        // node reads counted
  std::uint64_t scan_ticks = 0;   // sum of full six-node scan times, ticks
  std::uint64_t scans = 0;        // full scans counted

  // One node read that took `t` ticks since the previous read (or the scan's start).
  void add_node(std::uint64_t t) {
    node_ticks += t;
    ++nodes;
  }
  // One scan over all six nodes that took `t` ticks.
  void add_scan(std::uint64_t t) {
    scan_ticks += t;
    ++scans;
  }
  // Mean node time, ticks (0 before the first read).
  std::uint32_t mean_node() const { return nodes ? static_cast<std::uint32_t>(node_ticks / nodes) : 0; }
  // Mean full-scan time, ticks (0 until a scan had an active sensor on every node).
  std::uint32_t mean_scan() const { return scans ? static_cast<std::uint32_t>(scan_ticks / scans) : 0; }
};

}  // namespace robuter::us
