// SPDX-License-Identifier: GPL-3.0-or-later
// Saved place grids read back into one map of the floor: the planner's memory of an earlier run.
#include "modules/places/place_grid_memory.hpp"

#include <filesystem>
#include <system_error>

#include "modules/places/place_grid.hpp"

namespace robuter::places {

plan::Result<GridMemory> load_grid_memory(const PlaceGraph& graph, const std::string& dir,
                                          const plan::MapGeometry& geometry, std::uint8_t threshold) {
  GridMemory memory{plan::OccupancyMap(geometry, threshold), 0};
  for (const Place& p : graph.places()) {
    const std::string path = place_grid_path(dir, p.name);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) continue;
    auto grid = load_place_grid(path);
    if (!grid.ok()) return grid.error();
    if (grid.value().place != p.name)
      return plan::Error{path, 0, "the grid of place '" + grid.value().place + "', not of '" + p.name + "'"};
    const auto applied = apply_place_grid(grid.value(), memory.map);
    if (!applied.ok()) return plan::Error{path, 0, applied.error().message};
    ++memory.grids;
  }
  memory.map.clear_changes();
  return memory;
}

}  // namespace robuter::places
