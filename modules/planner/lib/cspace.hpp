// SPDX-License-Identifier: GPL-3.0-or-later
// Configuration-space layers: the map's obstacles dilated by a footprint mask, kept as a PassGrid.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "modules/planner/lib/cspace_stack.hpp"
#include "modules/planner/lib/footprint.hpp"
#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/planner/lib/pass_grid.hpp"
#include "modules/planner/lib/slice_bits.hpp"

namespace robuter::plan {

// A cell of a PassGrid whose class changed, with the class it had before.
struct ClassChange {
  std::uint32_t index;   // PassGrid index
  std::uint8_t before;   // CellClass before the update (after = grid.cls[index])
};

// Why: a point robot's grid straight from the map (MovingAI, or a pre-expanded map).
void pass_grid_from_map(const OccupancyMap& map, PassGrid& grid);

// One C-space layer: the map's obstacles dilated by a footprint mask. A cell is blocked when the
// footprint placed there meets an occupied cell, else free or unknown as the map says. The layer
// keeps only its classes (one byte per cell); the occupancy it tests against, and the per-cell
// marks its update needs, are the CSpaceStack shared by every layer of a planner.
// A full build dilates each row of the stack's occupancy bitsets by the mask's runs (two shifted
// ORs of 64-bit words per run, CSpaceStack::dilate_row: O(cells / 64 x mask rows)), then copies
// the row's own classes and marks the blocked cells. An update after a sync (CSpaceStack::begin_sync) keeps no counts: a newly occupied
// map cell blocks every cell whose footprint covers it (a run of them along a row by one span
// per mask row); a freed one re-tests only the blocked
// cells whose footprint covered it, each once per update, against the table (the mask's bounding
// box, then bands of runs, stopping at the first occupied cell); a free <-> unknown change re-classes that cell
// unless it is blocked.
// A layer that is only asked "blocked or not" (a turn-clearance slice) keeps no classes: it
// writes bit `slice` of a SliceBits shared by its stack of layers (build_bits, update_bits),
// by the same steps, so each bit says exactly whether the class layer would be blocked.
class CSpaceLayer {
 public:
  // Why: size for the map and compute everything once, from `stack` (reset for `map`).
  void build(const CSpaceStack& stack, const OccupancyMap& map, FootprintMask mask);
  // Why: build() for a caller without a stack (tests): one is made for the map.
  void build(const OccupancyMap& map, FootprintMask mask);

  // Why: the map moved under the layer (Planner::shift_map): recompute every class from the
  // stack (already reset for the moved map) with the mask kept, without allocating. The same
  // classes as build() on that map.
  void rebuild(const CSpaceStack& stack, const OccupancyMap& map);

  // Why: follow the map after beams: `cells` are the map indexes from OccupancyMap::changes()
  // that `stack` has folded (begin_sync, before end_sync). Cells whose class changed are
  // appended to `out` (each once per call, with its class before the call) when it is not null.
  void update(CSpaceStack& stack, const OccupancyMap& map, std::span<const std::uint32_t> cells,
              std::vector<ClassChange>* out);

  // Why: a turn-clearance layer: the same footprint test, kept as bit `slice` of `bits` (sized
  // by the caller for the map and every slice); grid() stays empty.
  void build_bits(const CSpaceStack& stack, const OccupancyMap& map, FootprintMask mask, SliceBits& bits,
                  int slice);
  void build_bits(const OccupancyMap& map, FootprintMask mask, SliceBits& bits, int slice);
  void update_bits(CSpaceStack& stack, const OccupancyMap& map, std::span<const std::uint32_t> cells,
                   SliceBits& bits, int slice);
  // Why: rebuild() for a turn-clearance layer: bit `slice` of `bits` recomputed from the stack.
  void rebuild_bits(const CSpaceStack& stack, const OccupancyMap& map, SliceBits& bits, int slice) const;

  const PassGrid& grid() const { return grid_; }
  const FootprintMask& mask() const { return mask_; }
  // Why: tests and pictures ask whether the footprint at a cell meets an obstacle.
  bool blocked(Cell c) const { return grid_.at(c) == kBlocked; }

 private:
  // A box of mask offsets (cells) over runs [first, last).
  struct Band {
    std::size_t first = 0, last = 0;  // runs
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // cells, offsets from the robot's cell (inclusive)
    bool exact = false;                // fewer than 65,536 cells: the table's count is exact
  };
  static constexpr std::size_t kBandRuns = 4;  // runs per band

  void index_mask();
  void index_core();
  bool meets(const CSpaceStack& stack, int x, int y) const;
  // Where a build or an update writes (cspace.cpp: the layer's classes, or one slice's bits).
  template <class Store>
  void fill(const CSpaceStack& stack, const OccupancyMap& map, Store& store) const;
  template <class Store>
  bool block_raised_by_window(Store& store, CSpaceStack& stack, const OccupancyMap& map,
                              std::span<const std::uint32_t> cells, std::vector<ClassChange>* out) const;
  template <class Store>
  void update_in(Store& store, CSpaceStack& stack, const OccupancyMap& map,
                 std::span<const std::uint32_t> cells, std::vector<ClassChange>* out) const;

  FootprintMask mask_;
  Band core_;                 // the largest box of cells wholly inside the mask (its runs unused):
                              // an obstacle in it settles a re-test at once
  bool core_valid_ = false;   // core_ holds a box (not for an empty mask, nor one the table
                              // cannot count exactly)
  Band box_;                  // the whole mask's bounding box
  bool box_exact_ = false;    // box_ holds < 65,536 cells (the table's count is exact)
  std::vector<Band> bands_;   // kBandRuns runs each, in order
  PassGrid grid_;             // the searchable result (empty for a bit layer)
};

}  // namespace robuter::plan
