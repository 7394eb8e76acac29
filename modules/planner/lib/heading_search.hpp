// SPDX-License-Identifier: GPL-3.0-or-later
// Optimal search in (x, y, heading slice) for a non-circular robot: seed 004's slices on a grid.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "modules/planner/lib/cost_field.hpp"
#include "modules/planner/lib/enclosure.hpp"
#include "modules/planner/lib/geometry.hpp"
#include "modules/planner/lib/bucket_ring.hpp"
#include "modules/planner/lib/indexed_heap.hpp"
#include "modules/planner/lib/pass_grid.hpp"
#include "modules/planner/lib/plan_result.hpp"
#include "modules/planner/lib/slice_bits.hpp"

namespace robuter::plan {

// Which moves a slice allows.
enum class MotionModel : std::uint8_t {
  Aligned,    // differential drive: translate only along the slice's heading (either way),
              // turn in place between slices; exactly what the robot can execute (default)
  Holonomic,  // all 8 moves in every slice (the footprint keeps the slice's heading)
};

// Options of the (x, y, heading) search.
struct HeadingOptions {
  MotionModel motion = MotionModel::Aligned;  // allowed moves within a slice
  double rotation_step_cost = 0.0;            // cells: cost of turning by one slice in place
  bool heap = false;                          // force the heap open list (tests compare)
};

// A* over states (cell, move slice). Moves: the allowed grid moves within a slice (both cells,
// and for a diagonal both side cells, free in that slice: slices are swept over their heading
// interval, so the footprint's translation along the heading is covered); rotation in place
// between slices when the cell is free in both (their union covers the turn). The goal is a cell
// at any heading. Heuristic: the cost field of a relaxation (the map dilated by the footprint's
// inscribed disc: free for the rectangle at some heading implies free for the disc), which is
// admissible and consistent; without one, octile distance. Open list: a BucketRing (exact, with
// reopening), or a 4-ary heap when unknown cells are far dearer.
//
// Lean states: a slice that allows no grid move (MotionModel::Aligned: 24 of 32 by default)
// only passes turns, so states exist only in the move slices; a turn edge joins a move slice to
// the next one up or down at the same cell, allowed exactly when every one-slice step between
// them is, and costs the steps' sum. This is the full (cell x slice) graph with its pass-through
// states contracted: costs are identical (tests/planner/test_lean_search.cpp checks against the
// full graph), and path() still lists every slice passed. States live in pages, one per tile of
// 8 x 8 cells (all move slices), taken from a pool sized once by reserve(): memory follows the
// cells a search touches, not the map's area. A search that needs more pages than the pool
// holds ends with PlanStatus::SearchLimit.
class HeadingSearch {
 public:
  static constexpr double kBucketWidth = 0.5;  // cells of f per open-list bucket
  static constexpr int kTileShift = 3;         // tiles of 8 x 8 cells
  static constexpr int kTileCells = 1 << (2 * kTileShift);  // cells per tile
  // States the pool holds by default: 262,144 (17 bytes each with the bucket ring, 37 with the
  // heap; resident only where a search writes). The seed 000 lab run's largest search took
  // 108 k (211 pages of 512); see docs/PLANNER.md.
  static constexpr std::size_t kDefaultStateBudget = std::size_t{1} << 18;
  // Expansions after which a search whose expanded cells still fit in EnclosureTest's window
  // asks whether the robot is shut in there (a search that would end unreachable after
  // exhausting a small component ends now; docs/PLANNER.md, "Shut in"); asked again after
  // kEnclosureGrowth times as many, at most kEnclosureTries times per search.
  static constexpr std::uint32_t kEnclosureAfter = 1024;
  static constexpr std::uint32_t kEnclosureGrowth = 4;
  static constexpr int kEnclosureTries = 2;

  // Why: size every buffer for slices of width x height (the only allocation); `state_budget`
  // caps the states one search may hold (whole pages; at least one page).
  void reserve(int width, int height, int slices,
               std::size_t state_budget = kDefaultStateBudget);

  // Why: the entry point; `slices` are K grids of one size; the path is then in path().
  // `turn_room` (null, or K slices of bits over the same grid): where turning in place needs
  // more room than translating (a body grown by a clearance), a turn k -> k±1 at a cell needs
  // the cell's bits k and k±1 clear — except at the start cell, where the robot already stands
  // and the body's own room is enough.
  PlanResult find(std::span<const PassGrid* const> slices, CellPose start, Cell goal,
                  const HeadingOptions& options, const CostModel& costs = {},
                  const CostField* heuristic = nullptr, const SliceBits* turn_room = nullptr);

  // Why: the same search in steps, for a caller whose activation must stay short: begin() checks
  // the ends and seeds nothing yet; it returns true when the outcome is already known (written
  // to `out`: outside, blocked, unreachable by the relaxation, already there). Each resume()
  // then pops at most `max_pops` states and returns true once the search has ended (`out` and
  // path() as find() gives them). Between steps the slices, the heuristic and the turn room
  // must hold still (the caller defers its map syncs); find() = begin() + one unbounded resume().
  bool begin(std::span<const PassGrid* const> slices, CellPose start, Cell goal, const HeadingOptions& options,
             const CostModel& costs, const CostField* heuristic, const SliceBits* turn_room, PlanResult& out);
  bool resume(std::uint32_t max_pops, PlanResult& out);
  bool pending() const { return run_.active; }
  // Why: drop a search in steps (its grids are about to change).
  void cancel() { run_.active = false; }

  // Start first; consecutive entries differ by one grid move or one slice step.
  const std::vector<CellPose>& path() const { return path_; }
  // Why: tests and figures: whether the last search ended by the shut-in proof.
  bool ended_shut_in() const { return shut_in_; }
  // Why: measurements and tests: pages (tiles) the last search took, and states per page.
  std::size_t pages_used() const { return used_; }
  std::size_t page_states() const { return std::size_t{1} << page_shift_; }
  std::size_t state_budget() const { return budget_; }

 private:
  // A tile's page in the current search.
  struct TileEntry {
    std::uint32_t stamp = 0;  // generation that gave the tile its page (else: none)
    std::uint32_t page = 0;   // pool page index
  };
  // The stored cell at a page's tile corner.
  struct PageOrigin {
    std::int32_t x;  // stored cells (grid x + 1)
    std::int32_t y;  // stored cells (grid y + 1)
  };

  // One search's inputs (begin()) and its progress between resume() steps.
  struct Run {
    std::span<const PassGrid* const> slices;  // the slice grids (the caller's, kept alive)
    CellPose start{};                         // cells, slice normalised
    Cell goal{};                              // cells
    HeadingOptions options{};                 // moves, turn cost
    CostModel costs{};                        // class costs
    const CostField* heuristic = nullptr;     // relaxation field, or null (octile)
    const SliceBits* turn_room = nullptr;     // grown-body bits, or null
    int m_count = 0;                          // move slots
    bool use_ring = false;                    // open list: ring (else heap)
    bool active = false;                      // begun, not yet ended
    bool seeded = false;                      // the start's states are queued
    PlanResult partial{};                     // expansions so far
    double best = CostField::kInfinity;       // cells: best goal cost so far
    std::uint32_t reached = 0;                // pool state of that goal
    bool limit = false;                       // the pool ran out
    std::uint32_t next_enclosure = kEnclosureAfter;  // expansions at which the shut-in test runs next
    int enclosure_tries = 0;                  // shut-in tests run
    int min_x = 1 << 30, max_x = -1;          // stored cells: expanded cells' columns so far
    int min_y = 1 << 30, max_y = -1;          // stored cells: their rows
  };
  Run run_;
  bool shut_in_ = false;  // the last search ended by EnclosureTest
  static constexpr std::uint32_t kFirstTouchPops = 256;  // pops a never-written page counts for
  std::size_t resident_pages_ = 0;  // pages some search has written (handed out in order)

  std::unique_ptr<double[]> g_;          // per pool state: cells, best cost from the start
  std::unique_ptr<std::uint8_t[]> meta_; // per pool state: parent (low 4 bits) | kSeen | kClosed
  std::size_t budget_ = 0;               // states in g_ and meta_
  std::vector<TileEntry> tiles_;         // per tile of the stored grid
  std::vector<PageOrigin> origin_;       // per page (budget_ / kTileCells at most)
  int tiles_x_ = 0;                      // tiles per stored row
  int page_shift_ = 0;                   // log2 of states per page (this search)
  std::size_t pages_ = 0;                // pages the pool holds (this search)
  std::size_t used_ = 0;                 // pages taken (this search)
  IndexedHeap open_;           // open list for very uneven costs
  std::vector<CellPose> path_; // last path, start first
  std::uint32_t gen_ = 0;      // generation stamp
  std::vector<const std::uint8_t*> cls_of_;  // per slice: its cell classes (this search)
  std::vector<std::uint8_t> allowed_;        // per slice: allowed move bits (this search)
  std::vector<int> move_slice_;              // per move slot: its slice (this search)
  std::vector<int> slot_of_;                 // per slice: its move slot, or -1 (this search)
  BucketRing ring_;            // open list when edge costs allow (else open_)
  EnclosureTest enclosure_;    // the shut-in proof
};

// Why: which of the 8 moves a slice allows under a motion model (bit m set = move m allowed).
std::uint8_t allowed_moves(int slice, int slices, MotionModel motion);

}  // namespace robuter::plan
