// SPDX-License-Identifier: GPL-3.0-or-later
// Test-only reference: the full-graph (cell x every slice) search the lean HeadingSearch replaced.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "modules/planner/lib/heading_search.hpp"

namespace robuter::plan {

// The search as it was before states lived only in move slices: one state per (cell, slice),
// turns one slice at a time. Kept to check the lean search's costs exactly.
// A* over states (cell, slice). Moves: the allowed grid moves within a slice (both cells, and
// for a diagonal both side cells, free in that slice: slices are swept over their heading
// interval, so the footprint's translation along the heading is covered); rotation in place to
// an adjacent slice when the cell is free in both (their union covers the turn). The goal is a
// cell at any heading. Heuristic: the cost field of a relaxation (the map dilated by the
// footprint's inscribed disc: free for the rectangle at some heading implies free for the disc),
// which is admissible and consistent; without one, octile distance. Open list: a BucketRing
// (exact, with reopening), or a 4-ary heap when unknown cells are far dearer.
class ReferenceHeadingSearch {
 public:
  static constexpr double kBucketWidth = 0.5;  // cells of f per open-list bucket

  // Why: size every buffer for slices of width x height (the only allocation).
  void reserve(int width, int height, int slices);

  // Why: the entry point; `slices` are K grids of one size; the path is then in path().
  // `turn_slices` (empty, or K grids of the same size): where turning in place needs more room
  // than translating (a body grown by a clearance), a turn k -> k±1 at a cell needs the cell
  // free in both of these slices instead — except for the turns at the start cell before the
  // robot's first move (departure states), where the body's own room is enough.
  PlanResult find(std::span<const PassGrid* const> slices, CellPose start, Cell goal,
                  const HeadingOptions& options, const CostModel& costs = {},
                  const CostField* heuristic = nullptr,
                  std::span<const PassGrid* const> turn_slices = {});

  const std::vector<CellPose>& path() const { return path_; }

 private:
  // Per state search data.
  struct Node {
    double g;             // cells: best cost from the start
    std::uint32_t stamp;  // generation that wrote it
    std::uint8_t parent;  // 0..7 grid move, 8 turned +1 slice, 9 turned -1 slice, kNoMove start,
                          // kFromDeparture + m: move m from the start cell before any move
    std::uint8_t closed;  // 1 once expanded
  };

  static constexpr std::uint8_t kFromDeparture = 16;  // parent code offset: a move from a departure state
  std::vector<Node> nodes_;    // slice-major: slice * stored + cell index; then the start cell's
                               // departure states, one per slice
  IndexedHeap open_;           // open list for very uneven costs
  std::vector<CellPose> path_; // last path, start first
  std::uint32_t gen_ = 0;      // generation stamp
  std::vector<const std::uint8_t*> cls_of_;  // per slice: its cell classes (this search)
  std::vector<const std::uint8_t*> turn_of_; // per slice: classes checked for turns (this search)
  std::vector<std::uint8_t> allowed_;        // per slice: allowed move bits (this search)
  BucketRing ring_;            // open list when edge costs allow (else open_)
};

}  // namespace robuter::plan
