// SPDX-License-Identifier: GPL-3.0-or-later
// A map's distance field (map_field.hpp).
#include "modules/localise/map_field.hpp"

#include <cstdint>
#include <vector>

namespace robuter::localise {

loc::DistanceField distance_field(const plan::OccupancyMap& map, double reach) {
  const auto& g = map.geometry();
  loc::FieldGeometry fg;
  fg.width = g.width;
  fg.height = g.height;
  fg.resolution = g.resolution;
  fg.origin = Eigen::Vector2d(g.origin.x, g.origin.y);
  std::vector<std::uint8_t> occupied(map.cell_count(), 0);
  for (std::uint32_t i = 0; i < occupied.size(); ++i) occupied[i] = map.state_at(i) == plan::CellState::Occupied ? 1 : 0;
  return loc::DistanceField(fg, occupied, reach);
}

}  // namespace robuter::localise
