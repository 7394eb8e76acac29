// SPDX-License-Identifier: GPL-3.0-or-later
// The passage finder's corner detection on the differences of a 72-sector scan (seed gate.c).
#pragma once

#include <cstdint>

#include "modules/ptu/scan_filter.hpp"

namespace robuter::gate {

using ptu::SectorValues;

// Thresholds of the corner detection (seed gate.h).
struct CornerSettings {
  std::int32_t margin_mm = 300;   // a difference above +margin opens a passage, below −margin closes it (MARGIN)
  int max_gap_sectors = 8;        // a passage spans fewer far sectors than this (seed: in_door < 8)
};

// A passage found in the scan: the two sectors that see its edges (seed get_corners).
struct CornerLock {
  bool locked = false;            // a passage was found
  int right = 0;                  // sector of the right-hand edge (the near sector before the jump up), 0..71
  int left = 0;                   // sector of the left-hand edge (the near sector after the jump down), 0..71
  std::int32_t right_value = 0;   // filtered range of the right edge's sector, mm
  std::int32_t left_value = 0;    // filtered range of the left edge's sector, mm
  int gap_sectors = 0;            // far sectors between the edges (seed in_door)
};

// seed get_corners(): every positive transition d[n] > margin is a candidate right edge, taken
// in sector order; walking counter-clockwise from it to the first d[n] ≤ −margin gives the left
// edge n + 1; the first candidate with fewer than max_gap_sectors far sectors locks. Bounded
// (the seed's walk had no end when no negative transition followed, and its lock flag started
// uninitialised).
CornerLock find_corners(const SectorValues& differences, const SectorValues& filtered, const CornerSettings& s = {});

// seed get_center(): the sector midway between the edges, counter-clockwise from right to left,
// wrapped into 0..71 (the seed could return a negative sector across the wrap).
int center_sector(int left, int right);

}  // namespace robuter::gate
