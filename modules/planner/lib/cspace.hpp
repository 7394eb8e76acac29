// SPDX-License-Identifier: GPL-3.0-or-later
// Configuration-space layers: the map's obstacles dilated by a footprint mask, kept as a PassGrid.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "modules/planner/lib/footprint.hpp"
#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/planner/lib/pass_grid.hpp"

namespace robuter::plan {

// A cell of a PassGrid whose class changed, with the class it had before.
struct ClassChange {
  std::uint32_t index;   // PassGrid index
  std::uint8_t before;   // CellClass before the update (after = grid.cls[index])
};

// Why: a point robot's grid straight from the map (MovingAI, or a pre-expanded map).
void pass_grid_from_map(const OccupancyMap& map, PassGrid& grid);

// One C-space slice: for every cell, how many occupied cells the footprint placed there would
// meet; the cell is blocked when that count is non-zero, else free or unknown as the map says.
// A full build uses per-row prefix sums (O(cells x mask rows)); an update stamps the mask
// around each changed map cell, so a few new obstacles cost a few mask areas.
class CSpaceLayer {
 public:
  // Why: size for the map and compute everything once.
  void build(const OccupancyMap& map, FootprintMask mask);

  // Why: follow the map after beams: `cells` are map indexes from OccupancyMap::changes().
  // Cells whose class changed are appended to `out` (each once per call) when it is not null.
  void update(const OccupancyMap& map, std::span<const std::uint32_t> cells,
              std::vector<ClassChange>* out);

  const PassGrid& grid() const { return grid_; }
  const FootprintMask& mask() const { return mask_; }
  // Why: tests and pictures ask whether the footprint at a cell meets an obstacle.
  bool blocked(Cell c) const { return grid_.at(c) == kBlocked; }

 private:
  void reclass(const OccupancyMap& map, std::uint32_t map_index, std::vector<ClassChange>* out);

  FootprintMask mask_;
  std::vector<std::uint16_t> cover_;   // per map cell: occupied cells met by the footprint there
  std::vector<std::uint8_t> counted_;  // per map cell: 1 when counted as occupied in cover_
  std::vector<std::uint8_t> marked_;   // per map cell: already reported in this update
  PassGrid grid_;                      // the searchable result
};

}  // namespace robuter::plan
