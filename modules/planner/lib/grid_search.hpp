// SPDX-License-Identifier: GPL-3.0-or-later
// One-shot 2D searches on a PassGrid: optimal A* (octile) and the thesis' breadth-first search.
#pragma once

#include <cstdint>
#include <vector>

#include "modules/planner/lib/geometry.hpp"
#include "modules/planner/lib/indexed_heap.hpp"
#include "modules/planner/lib/pass_grid.hpp"
#include "modules/planner/lib/plan_result.hpp"

namespace robuter::plan {

// Which 2D search to run.
enum class SearchMode : std::uint8_t {
  Optimal,  // A*, octile costs, octile heuristic: shortest path (default)
  Bfs,      // the thesis: breadth-first, fewest moves, orthogonal neighbours tried first
};

// Optimal mode, uniform costs (unknown cells cost what free cells cost, the default): jump
// point search (Harabor & Grastien) with the no-corner-cutting rules: A* over jump points only,
// straight and diagonal runs scanned on the class array, a 4-ary heap as open list. Exact: the
// same lengths as A* (checked on all 2,690 MovingAI problems).
//
// Optimal mode, unknown cells dearer: A* whose open list is a ring of f-buckets (doubly linked
// through per-node arrays, so push, move and pop are O(1) and nothing is allocated). Nodes
// within one bucket (f within kBucketWidth) are taken last-in first-out; since that order is
// only approximate, a closed node whose cost still improves is reopened, and the search stops
// only when the lowest non-empty bucket starts at or above the best goal cost: the result is
// exact. If the costs make the ring too large (huge unknown_cost) a 4-ary heap is used.
//
// 8-connected search without corner cutting (a diagonal move needs both side cells
// traversable). All per-node state lives in arrays sized by reserve(); a generation stamp
// marks which entries belong to the current search, so nothing is cleared between searches
// and a search never allocates once the grid size is known.
class GridSearch {
 public:
  static constexpr double kBucketWidth = 0.5;   // cells of f per bucket
  static constexpr std::uint32_t kNil = 0xFFFFFFFFu;

  GridSearch() = default;
  GridSearch(int width, int height) { reserve(width, height); }

  // Why: size every buffer for grids up to width x height (the only allocation).
  void reserve(int width, int height);

  // Why: the one entry point; the path (start..goal cells) is then in path().
  PlanResult find(const PassGrid& grid, Cell start, Cell goal, SearchMode mode,
                  const CostModel& costs = {});

  const std::vector<Cell>& path() const { return path_; }

  // Which optimal algorithm find() uses (Auto: jump points when costs are uniform, else
  // buckets); tests and the bench pin one to compare them.
  enum class Engine : std::uint8_t { Auto, JumpPoints, Buckets, Heap };
  void set_engine(Engine e) { engine_ = e; }

  // Why: jump points pay off where obstacles form walls and blocks and the free space forms
  // open areas or corridors (rooms, streets, mazes, the game maps) and lose to the bucket A*
  // where obstacles are scattered cells (random grids, even at 1 %) or the free space is a
  // fragmented mesh (random grids at 40 %: 1.2-1.3x slower, measured by robuter-plan-bench).
  // Auto samples up to 256 cells at fixed positions and uses jump points when
  // scattered_fraction() < kScatteredLimit and run_fraction() >= kRunLimit.
  //
  // scattered_fraction: the share of sampled blocked cells with at most one blocked side
  // neighbour (an obstacle-free sample counts as scattered: A* crosses open space in a
  // straight line).
  double scattered_fraction(const PassGrid& grid);
  // run_fraction: the share of sampled traversable cells where a jump runs on: all eight
  // neighbours traversable (open area) or both side neighbours of one axis blocked (corridor).
  double run_fraction(const PassGrid& grid);
  // Why: Auto's choice for uniform costs on this grid.
  bool prefers_jump_points(const PassGrid& grid) {
    return scattered_fraction(grid) < kScatteredLimit && run_fraction(grid) >= kRunLimit;
  }
  static constexpr std::size_t kSamples = 256;
  static constexpr double kScatteredLimit = 0.3;
  static constexpr double kRunLimit = 0.4;

 private:
  void next_generation();
  void sample_cells(const PassGrid& grid);
  PlanResult astar(const PassGrid& grid, std::uint32_t s, std::uint32_t t, const CostModel& c);
  PlanResult astar_buckets(const PassGrid& grid, std::uint32_t s, std::uint32_t t,
                           const CostModel& c);
  PlanResult astar_jps(const PassGrid& grid, std::uint32_t s, std::uint32_t t,
                       const CostModel& c);
  PlanResult bfs(const PassGrid& grid, std::uint32_t s, std::uint32_t t, const CostModel& c);
  void build_path(const PassGrid& grid, const MoveTable& mt, std::uint32_t s, std::uint32_t t,
                  PlanResult& r, const CostModel& c);

  // Per stored cell search state, as separate arrays (the hot check reads only mark_).
  std::vector<std::uint32_t> mark_;    // generation << 1 | closed; other generations = unseen
  std::vector<double> g_;              // cells: best cost from the start (valid when seen)
  std::vector<std::uint8_t> parent_;   // move that reached the cell, kNoMove for the start
  std::vector<std::uint32_t> next_;    // optimal mode: next node in its bucket list, or kNil
  std::vector<std::uint32_t> prev_;    // optimal mode: previous node in its list, or kNil
  std::vector<std::uint32_t> queue_;   // BFS FIFO
  std::vector<std::uint32_t> from_;    // jump point search: the jump point a node came from
  std::vector<std::uint32_t> head_;    // per ring bucket: first node, or kNil
  IndexedHeap open_;                   // heap fallback's open list
  std::vector<Cell> path_;             // last path, start first
  Engine engine_ = Engine::Auto;       // optimal algorithm selection
  std::vector<std::uint32_t> samples_; // cells sampled by scattered_fraction()
  int sample_width_ = -1;              // cells: grid size samples_ was made for
  int sample_height_ = -1;             // cells
  std::uint32_t gen_ = 0;              // current generation (marks are gen_ << 1 | closed)
};

}  // namespace robuter::plan
