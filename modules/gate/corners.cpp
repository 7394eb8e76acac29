// SPDX-License-Identifier: GPL-3.0-or-later
// Corner detection and passage centre, seed gate.c with its loop bounded and its wrap fixed.
#include "modules/gate/corners.hpp"

namespace robuter::gate {

using ptu::kSectors;
using ptu::wrap_sector;

CornerLock find_corners(const SectorValues& d, const SectorValues& f, const CornerSettings& s) {
  CornerLock out;
  for (int right = 0; right < kSectors; ++right) {
    if (d[static_cast<std::size_t>(right)] <= s.margin_mm) continue;
    int n = right;
    int gap = 0;
    bool closed = false;
    // Walk at most once round the circle looking for the closing (negative) transition.
    for (int step = 1; step < kSectors; ++step) {
      n = wrap_sector(n + 1);
      ++gap;
      if (d[static_cast<std::size_t>(n)] <= -s.margin_mm) {
        closed = true;
        break;
      }
    }
    if (!closed || gap >= s.max_gap_sectors) continue;
    out.locked = true;
    out.right = right;
    out.left = wrap_sector(n + 1);
    out.gap_sectors = gap;
    out.right_value = f[static_cast<std::size_t>(out.right)];
    out.left_value = f[static_cast<std::size_t>(out.left)];
    return out;
  }
  return out;
}

int center_sector(int left, int right) {
  if (left < right) left += kSectors;
  return wrap_sector((left + right) / 2);
}

}  // namespace robuter::gate
