// SPDX-License-Identifier: GPL-3.0-or-later
// One-slot hand-off of a place's grid from the planner (kernel thread) to the place grid writer.
#pragma once

#include <algorithm>
#include <cstddef>

#include "kernel/handoff.hpp"
#include "modules/places/place_grid.hpp"

namespace robuter::places {

// One grid in the slot.
struct PlaceGridSlot {
  std::size_t place = 0;  // the place's index in the graph
  PlaceGrid grid;         // its cells (grid.place is set by the writer)
};

// The planner cuts a place's grid into the slot in the activation its scan ended; the writer
// (another thread, or a test between ticks) saves it and frees the slot (OneSlot: never waited
// for, drops counted).
class PlaceGridMailbox : public OneSlot<PlaceGridSlot> {
 public:
  // Why: the allocation point (start-up): room for the largest place's box on cells of
  // `resolution` (m), wherever the moving map's cells fall (a cell more each way).
  void reserve(const PlaceGraph& graph, double resolution) {
    plan::MapGeometry cells;
    cells.resolution = resolution;
    std::size_t most = 0;
    for (std::size_t k = 0; k < graph.places().size(); ++k) {
      const PlaceBox b = place_box(graph, k, cells);
      most = std::max(most, static_cast<std::size_t>(b.width + 1) * static_cast<std::size_t>(b.height + 1));
    }
    value().grid.cells.reserve(most);
  }
};

}  // namespace robuter::places
