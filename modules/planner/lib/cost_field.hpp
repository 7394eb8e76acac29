// SPDX-License-Identifier: GPL-3.0-or-later
// Incremental cost-to-goal field: a reverse Dijkstra from the goal, repaired after map changes.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "modules/planner/lib/bucket_ring.hpp"
#include "modules/planner/lib/cspace.hpp"
#include "modules/planner/lib/indexed_heap.hpp"
#include "modules/planner/lib/pass_grid.hpp"
#include "modules/planner/lib/plan_result.hpp"

namespace robuter::plan {

// Shortest cost from every cell to one goal over a PassGrid (8-connected, no corner cutting,
// CostModel costs), with each cell's next move toward the goal. Built once per goal by a full
// Dijkstra; after cells change class, only the affected part is recomputed:
//  * cells whose shortest route used a cell or an edge that got worse (their subtree in the
//    shortest-path tree) are reset and re-seeded from their unaffected neighbours;
//  * cells that got better, and their neighbours (new diagonal edges), are re-seeded;
//  * one Dijkstra pass from those seeds settles everything that moved.
// The path from any start is then read off the next-move pointers in O(path length), so a
// moving robot replans toward a fixed goal without searching again. Exact (same costs as A*).
class CostField {
 public:
  static constexpr double kInfinity = std::numeric_limits<double>::infinity();
  static constexpr double kBucketWidth = 0.5;  // cells of cost per bucket (full computation)

  // Why: size for grids up to width x height (the only allocation).
  void reserve(int width, int height);

  // Why: full computation for a goal on a grid; the grid must stay alive and is read again by
  // update(). Returns false if the goal is outside or blocked (then every cell is unreachable).
  bool compute(const PassGrid& grid, Cell goal, const CostModel& costs = {});

  // Why: the same computation in steps, for a caller with a time budget per activation: begin()
  // seeds the goal, each step() settles at most `max_settled` cells and returns true once the
  // field is complete (compute() = begin() + one unbounded step()). Until then the grid must not
  // change, cost() and path_from() are not to be used, and update() does nothing.
  void begin(const PassGrid& grid, Cell goal, const CostModel& costs = {});
  bool step(std::uint32_t max_settled);
  bool pending() const { return pending_; }
  // Why: drop a computation in steps (the grid it was for is about to change wholesale).
  void cancel() { pending_ = false; use_ring_ = false; }

  // Why: repair after `changes` (the grid already holds the new classes).
  void update(std::span<const ClassChange> changes);

  bool valid() const { return grid_ != nullptr; }
  Cell goal() const { return goal_; }
  // Cost to the goal from a cell (cells); kInfinity when unreachable or outside.
  double cost(Cell c) const;
  double cost_at(std::uint32_t index) const { return dist_[index]; }

  // Why: read the path off the field; fills `path` (start first) and returns the outcome.
  PlanResult path_from(Cell start, std::vector<Cell>& path) const;

  // Effort of the last compute() or update(): nodes settled (for figures and tests).
  std::uint32_t last_settled() const { return settled_; }
  std::uint32_t last_invalidated() const { return invalidated_; }

 private:
  bool edge_ok(std::uint32_t u, int m) const;
  void relax_from(std::uint32_t u);
  bool run(std::uint32_t max_settled);  // true when the queue is empty
  void seed(std::uint32_t v);
  void push_or_lower(std::uint32_t v, double old, double d);
  void invalidate_subtree(std::uint32_t root);

  const PassGrid* grid_ = nullptr;             // the grid the field is for
  CostModel costs_;                            // costs the field was computed with
  std::array<std::array<std::array<double, 3>, 3>, 8> table_{};  // move costs by classes
  MoveTable mt_;                               // index offsets for grid_->stride
  Cell goal_;                                  // cells
  std::uint32_t goal_index_ = 0;               // PassGrid index of the goal
  std::vector<double> dist_;                   // per stored cell: cost to goal (cells)
  std::vector<std::uint8_t> next_;             // per stored cell: move toward the goal, kNoMove
  std::vector<std::uint8_t> in_heap_;          // per stored cell: 1 while in the heap
  std::vector<std::uint8_t> reset_;            // per stored cell: 1 while reset in an update
  std::vector<std::uint32_t> work_;            // reset cells of the current update
  IndexedHeap heap_;                           // repair queue keyed by dist (seeds spread wide)
  BucketRing ring_;                            // full computation's queue (one seed)
  bool use_ring_ = false;                      // run() takes from ring_ instead of heap_
  bool pending_ = false;                       // begin() done, the last step() not yet
  std::uint32_t settled_ = 0;                  // nodes popped by the last run
  std::uint32_t invalidated_ = 0;              // cells reset by the last update
};

}  // namespace robuter::plan
