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

}  // namespace robuter::plan
