// SPDX-License-Identifier: GPL-3.0-or-later
// The place grids an earlier run saved, read back at start-up into one map of the floor.
#pragma once

#include <cstddef>
#include <string>

#include "modules/places/place_graph.hpp"
#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/planner/lib/result.hpp"

namespace robuter::places {

// What the earlier runs left: the floor's cells their grids knew, and how many grids there were.
struct GridMemory {
  plan::OccupancyMap map;     // on `geometry`'s cells: unknown where no grid knew the cell
  std::size_t grids = 0;      // place grids read
};

// Why: seed 003 keeps its grids for the run; here a later run starts from them
// ([places] load_grids). For each place of `graph`, `<dir>/<place>.txt` if it exists is read
// (load_place_grid, strict) and applied (apply_place_grid: same cells, or an error). The first
// error is the answer, naming the file (and line): a broken grid stops the start-up, it is not
// skipped. A grid naming another place is an error. Files that are no place's are not read.
// Allocates (start-up only).
plan::Result<GridMemory> load_grid_memory(const PlaceGraph& graph, const std::string& dir,
                                          const plan::MapGeometry& geometry, std::uint8_t threshold);

}  // namespace robuter::places
