// SPDX-License-Identifier: GPL-3.0-or-later
// The window rendering: one character per cell, top row first.
#include "modules/planner/map_window.hpp"

namespace robuter::planner {

void render_window(const plan::OccupancyMap& map, plan::Cell center, int side, std::span<char> out) {
  const int half = side / 2;
  std::size_t i = 0;
  for (int row = 0; row < side; ++row) {
    const int y = center.y + half - row;
    for (int col = 0; col < side && i < out.size(); ++col, ++i) {
      const plan::Cell c{center.x - half + col, y};
      char ch = '.';
      if (c == center) ch = 'P';
      else if (map.contains(c)) {
        switch (map.state(c)) {
          case plan::CellState::Free: ch = ' '; break;
          case plan::CellState::Occupied: ch = '#'; break;
          case plan::CellState::Unknown: ch = '.'; break;
        }
      }
      out[i] = ch;
    }
  }
}

}  // namespace robuter::planner
