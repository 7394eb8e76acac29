// SPDX-License-Identifier: GPL-3.0-or-later
// Text rendering of occupancy-map windows in seed 003's characters.
#include "modules/planner/lib/text_render.hpp"

namespace robuter::plan {

std::string render_text(const OccupancyMap& map, int x0, int y0, int width, int height,
                        std::optional<Cell> robot) {
  std::string out;
  if (width <= 0 || height <= 0) return out;
  out.reserve(static_cast<std::size_t>(width + 1) * static_cast<std::size_t>(height));
  for (int y = y0 + height - 1; y >= y0; --y) {
    for (int x = x0; x < x0 + width; ++x) {
      const Cell c{x, y};
      if (robot && *robot == c) {
        out += 'P';
        continue;
      }
      if (!map.contains(c)) {
        out += '.';
        continue;
      }
      switch (map.state(c)) {
        case CellState::Unknown: out += '.'; break;
        case CellState::Occupied: out += '#'; break;
        case CellState::Free: out += ' '; break;
      }
    }
    out += '\n';
  }
  return out;
}

std::string render_around(const OccupancyMap& map, Cell robot, int half) {
  return render_text(map, robot.x - half, robot.y - half, 2 * half + 1, 2 * half + 1, robot);
}

std::string render_thesis_log(const PassGrid& expanded, Cell start, Cell goal) {
  std::string out;
  out.reserve(static_cast<std::size_t>(expanded.width + 1) * static_cast<std::size_t>(expanded.height));
  for (int y = expanded.height - 1; y >= 0; --y) {
    for (int x = 0; x < expanded.width; ++x) {
      const Cell c{x, y};
      const bool blocked = expanded.at(c) == kBlocked;
      if (c == start) out += blocked ? 'M' : 'O';
      else if (c == goal) out += 'D';
      else out += blocked ? 'X' : ' ';
    }
    out += '\n';
  }
  return out;
}

}  // namespace robuter::plan
