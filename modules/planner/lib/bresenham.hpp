// SPDX-License-Identifier: GPL-3.0-or-later
// Bresenham's line between two cells, as the thesis rasterises obstacle edges and sonar beams.
#pragma once

#include "modules/planner/lib/geometry.hpp"

namespace robuter::plan {

// Why: one integer line walker for polygon edges and beams; visits a..b inclusive, stops early
// when `visit(x, y)` returns false. Works in all octants; the cells form an 8-connected chain.
template <class Visit>
void for_each_line_cell(Cell a, Cell b, Visit&& visit) {
  const int dx = b.x > a.x ? b.x - a.x : a.x - b.x;
  const int dy = b.y > a.y ? a.y - b.y : b.y - a.y;  // -|dy|
  const int sx = a.x < b.x ? 1 : -1;
  const int sy = a.y < b.y ? 1 : -1;
  int err = dx + dy;
  int x = a.x;
  int y = a.y;
  for (;;) {
    if (!visit(x, y)) return;
    if (x == b.x && y == b.y) return;
    const int e2 = 2 * err;
    if (e2 >= dy) {
      err += dy;
      x += sx;
    }
    if (e2 <= dx) {
      err += dx;
      y += sy;
    }
  }
}

}  // namespace robuter::plan
