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
#include "modules/planner/lib/lean_graph.hpp"
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
  // A page holds one tile's states in 1 << kPageSlotShift move slots (fewer when the search has
  // fewer): searches fill a tile's slots unevenly (a kept tree touched 44 % of a whole tile's
  // states, 70 % of a tile's states per slot), so pages per slot waste less memory
  // (docs/PLANNER.md, "Pages per move slot").
  static constexpr int kPageSlotShift = 0;
  // States the pool holds by default: 262,144 (17 bytes each with the bucket ring, 37 with the
  // heap; resident only where a search writes). The seed 000 lab run's largest search took
  // 108 k (211 pages of 512); see docs/PLANNER.md.
  static constexpr std::size_t kDefaultStateBudget = std::size_t{1} << 18;
  // The kept tree's states at most (whole pages of its pool), so that it costs a bounded share
  // of memory (docs/PLANNER.md, "The kept tree", "Pages per move slot"): 163,840 (2.8 MB at 18
  // bytes a state), what the 300 x 300 bench map's tree needs for replans >= 10x.
  static constexpr std::size_t kTreeStateBudget = 5 * (std::size_t{1} << 15);
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
  // the cell's bits k and k±1 clear — except for the turns the robot makes where it stands,
  // before its first move: there the body's own room is enough.
  PlanResult find(std::span<const PassGrid* const> slices, CellPose start, Cell goal,
                  const HeadingOptions& options, const CostModel& costs = {},
                  const CostField* heuristic = nullptr, const SliceBits* turn_room = nullptr);

  // Why: the same search in steps, for a caller whose activation must stay short: begin() checks
  // the ends and seeds nothing yet; it returns true when the outcome is already known (written
  // to `out`: outside, blocked, unreachable by the relaxation, already there). Each resume()
  // then pops at most `max_pops` states and returns true once the search has ended (`out` and
  // path() as find() gives them). Between steps the slices, the heuristic and the turn room
  // must hold still (the caller defers its map syncs); find() = begin() + one unbounded resume().
  // `tree` (null, or a search whose backward tree is kept(), on the same slices and options):
  // its values bound the cost to the goal from below, and a state whose tree path still holds is
  // an end: the plan is the path to it and its tree path on (docs/PLANNER.md, "The kept tree").
  bool begin(std::span<const PassGrid* const> slices, CellPose start, Cell goal, const HeadingOptions& options,
             const CostModel& costs, const CostField* heuristic, const SliceBits* turn_room, PlanResult& out,
             HeadingSearch* tree = nullptr);
  // Why: the kept tree: a search from the goal's states (every move slot free there, cost 0)
  // towards `robot`, with the grown body's turn rule everywhere; the robot's own turns before it
  // moves (the body's room) end it. Its heuristic is consistent and admissible for the cost to
  // the robot: the larger of the octile distance and goal_field(robot) - goal_field(cell) (the
  // relaxation's cost field to the goal, by the triangle inequality; `goal_field` must stay as it
  // is while the tree is kept). resume() runs it; it ends when every queued key exceeds the
  // robot's cost, so that every state whose key is at most that cost holds its exact cost to the
  // goal. Found or Unreachable (exhausted) keep the tree; SearchLimit does not. The slices and
  // the turn room must stay alive while it is kept; the map may then only raise costs.
  void begin_backward(std::span<const PassGrid* const> slices, CellPose robot, Cell goal, const HeadingOptions& options,
                      const CostModel& costs, const CostField* goal_field, const SliceBits* turn_room);
  bool kept() const { return kept_; }
  // Why: the kept tree's bound: the robot's cost when it was made (infinity: the goal's states
  // were exhausted without reaching the robot).
  double kept_bound() const { return bound_; }
  void forget() { kept_ = false; }
  // The kept tree as a forward search reads it (heading_tree.cpp). A state's key is its cost
  // to the goal plus the robot field at its cell; a state whose key is at most the bound
  // (settled) holds its exact cost; any other state's cost is at least the bound minus the field.
  static constexpr std::uint32_t kNoState = 0xFFFFFFFFu;
  // Why: a lower bound on the cost to the goal from stored cell (x, y) (index `cell`) in move
  // slot `slot`; `settled` gets the tree state when its value is exact, else kNoState.
  double tree_bound(int x, int y, int slot, std::uint32_t cell, std::uint32_t& settled) const;
  // Why: whether a settled state's tree path still exists at the same cost in the slices as they
  // are now (costs only rose since the tree was made: then its value is still exact). Memoised
  // per epoch (new_epoch(): the slices changed).
  bool tree_valid(std::uint32_t state);
  void new_epoch();
  bool resume(std::uint32_t max_pops, PlanResult& out);
  bool pending() const { return run_.active; }
  // Why: a kept tree's search is under way (begin_backward(), not yet ended).
  bool growing() const { return run_.active && run_.backward; }
  // Why: a caller sharing one budget between searches: states expanded by a search in steps
  // before its current step.
  std::uint32_t expanded_so_far() const { return run_.partial.expanded; }
  // Why: drop a search in steps (its grids are about to change).
  void cancel() {
    if (run_.active && run_.backward) kept_ = false;
    run_.active = false;
  }

  // Start first; consecutive entries differ by one grid move or one slice step.
  const std::vector<CellPose>& path() const { return path_; }
  // Why: tests and figures: whether the last search ended by the shut-in proof.
  bool ended_shut_in() const { return shut_in_; }
  // Why: measurements and tests: pages (tiles) the last search took, and states per page.
  std::size_t pages_used() const { return used_; }
  std::size_t page_states() const { return std::size_t{1} << page_shift_; }
  std::size_t state_budget() const { return budget_; }

 private:
  // meta_ bits of a pool state, and its parent codes (0..7: the grid move that led here).
  static constexpr std::uint8_t kParentMask = 0x0F;  // how the state was reached
  static constexpr std::uint8_t kSeen = 0x10;        // reached in this search (g_ is valid)
  static constexpr std::uint8_t kClosed = 0x20;      // expanded
  static constexpr std::uint8_t kSettled = 0x40;     // a kept tree's state whose cost is exact
  static constexpr std::uint8_t kTurnedUp = 8;       // turned up from the move slot below
  static constexpr std::uint8_t kTurnedDown = 9;     // turned down from the move slot above
  static constexpr std::uint8_t kSeedUp = 10;        // turned up from the start's slice, where it stands
  static constexpr std::uint8_t kSeedDown = 11;      // turned down from the start's slice, where it stands
  static constexpr std::uint8_t kStartState = 15;    // a seed: the start (the goal, backward)

  // Why: keys this close above the settle level count as settled too (rounding), cells.
  static double settle_slack(double bound) { return 1e-9 * (1.0 + bound); }
  // Why: how far past the robot's cost the tree settles keys (cells), pool permitting: states a
  // little off the robot's optimal paths hold exact costs too, so that a replan's detour round
  // new obstacles meets them soon. 5 % of the cost, and 5 cells (docs/PLANNER.md: measured).
  static double tree_margin(double cost) { return cost == CostField::kInfinity ? 0.0 : 0.05 * cost + 5.0; }

  // Why: at the end of a kept tree's search: mark the states whose cost is exact (kSettled):
  // those whose key is below the robot's cost (every queued key is at least that), and the
  // states of the robot's own tree path from the state that reached it (an optimal path's). In
  // steps like the search (a walk over every page the tree used: up to 6 ms at once in the seed
  // 000 lab run): at most `max_states` pool states per call (whole pages, one at least); true
  // once done, with the tree kept and `out` its result; until then growing() and not kept().
  bool settle_step(std::size_t max_states, PlanResult& out);
  static constexpr std::size_t kSettleStatesPerPop = 4;  // pool states a step marks per pop of its budget
  // Why: the kept tree's heuristic at stored cell (x, y) of index `cell` (begin_backward()),
  // consistent: a move changes only the cell's part, a turn of n slices only the slot's, by at
  // most n turn steps.
  // The cell's part (the octile distance, and the goal field's drop from the robot's cell) plus
  // the slot's (the turning from the robot's slice to the slot's, which no path avoids).
  double toward_robot(int x, int y, std::uint32_t cell) const;
  double toward_robot(int x, int y, std::uint32_t cell, int slot) const {
    return toward_robot(x, y, cell) + slot_turn_[static_cast<std::size_t>(slot)];
  }
  // Why: append an optimal path on from a valid settled state (the state itself excluded, goal
  // last), straight on where that costs no more; `last_move` is the move that led to the state
  // (-1: none).
  void append_tree_path(std::uint32_t state, int last_move, std::vector<CellPose>& out);
  // Why: the tree's state at stored cell (x, y) in `slot`, or kNoState if it never reached it.
  std::uint32_t state_at(int x, int y, int slot) const;
  // What tree_valid() and append_tree_path() read of the tree's graph, as the slices are now.
  struct TreeEdges {
    int k_count;                                          // slices over the full turn
    int m_count;                                          // move slots
    std::uint32_t stride;                                 // stored cells per row
    MoveTable mt;                                         // move offsets
    std::array<std::array<std::array<double, 3>, 3>, 8> cost;  // cells: move cost by classes
    double turn;                                          // cells per slice turned
    LeanGraph lg;                                         // the turn rule's graph
    bool grown;                                           // turns need the grown body's room
  };
  TreeEdges tree_edges() const;
  // Why: one state's place: stored cell and move slot.
  void place_of(std::uint32_t s, int& x, int& y, int& slot) const;
  // Why: walk parents back from pool state `s` to a seed, listing every slice a turn passes
  // (s first); counts grid moves.
  void walk_back(std::uint32_t s, std::vector<CellPose>& out) const;

  // Why: the index in tiles_ of stored cell (x, y)'s page for move slot `slot` (its tile's slot
  // group); and the pool state of (x, y, slot) in that page.
  // The arithmetic once, with the layout as arguments (resume() passes its locals).
  static std::size_t entry_index(int tiles_x, int group_shift, int slot_bits, int x, int y, int slot) {
    const auto tile = static_cast<std::size_t>((y >> kTileShift) * tiles_x + (x >> kTileShift));
    return (tile << group_shift) | static_cast<std::size_t>(slot >> slot_bits);
  }
  static std::uint32_t state_index(int page_shift, int slot_bits, std::uint32_t page, int x, int y, int slot) {
    constexpr int tmask = (1 << kTileShift) - 1;
    const auto local_slot = static_cast<std::uint32_t>(slot & ((1 << slot_bits) - 1));
    return (page << page_shift) | (local_slot << (2 * kTileShift)) |
           (static_cast<std::uint32_t>(y & tmask) << kTileShift) | static_cast<std::uint32_t>(x & tmask);
  }
  std::size_t entry_of(int x, int y, int slot) const {
    return entry_index(tiles_x_, group_shift_, slot_bits_, x, y, slot);
  }
  std::uint32_t state_in(std::uint32_t page, int x, int y, int slot) const {
    return state_index(page_shift_, slot_bits_, page, x, y, slot);
  }

  // A tile's page (of one slot group) in the current search.
  struct TileEntry {
    std::uint16_t stamp = 0;  // generation that gave the tile its page (else: none)
    std::uint16_t page = 0;   // pool page index (kMaxPages at most)
  };
  static constexpr std::size_t kMaxPages = std::size_t{1} << 16;  // pages one search may take
  // The stored cell at a page's tile corner.
  struct PageOrigin {
    std::int32_t x;     // stored cells (grid x + 1)
    std::int32_t y;     // stored cells (grid y + 1)
    std::int32_t slot;  // the page's first move slot
  };
  // Why: the place of a state from its index within its page (`local`) and the page's origin.
  static void place_in(std::uint32_t local, const PageOrigin& o, int& x, int& y, int& slot) {
    constexpr auto tmask = static_cast<std::uint32_t>((1 << kTileShift) - 1);
    slot = o.slot + static_cast<int>(local >> (2 * kTileShift));
    x = o.x + static_cast<int>(local & tmask);
    y = o.y + static_cast<int>((local >> kTileShift) & tmask);
  }

  // One search's inputs (begin()) and its progress between resume() steps.
  // What a search is asked: the same fields for a search from the robot and one from the goal.
  struct Problem {
    std::span<const PassGrid* const> slices;  // the slice grids (the caller's, kept alive)
    CellPose start{};                         // cells, slice normalised
    Cell goal{};                              // cells
    HeadingOptions options{};                 // moves, turn cost
    CostModel costs{};                        // class costs
    const CostField* heuristic = nullptr;     // relaxation field, or null (octile)
    const SliceBits* turn_room = nullptr;     // grown-body bits, or null
  };
  struct Run {
    Problem in{};                             // what was asked
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
    bool backward = false;                    // begin_backward(): a kept tree from the goal
    HeadingSearch* tree = nullptr;            // forward: the kept tree it ends on, or null
    std::uint32_t reached_tree = kNoState;    // forward: the tree state the best end is on, or none
    bool proven = false;                      // backward: every queued key reached the robot's cost
    bool settling = false;                    // backward: the search ended, its states being settled
    std::size_t settle_page = 0;              // backward: the next page settle_step() marks
  };
  // Why: per-search tables (allowed moves, slots), the generation and the page size; returns
  // the move slots.
  int prepare(std::span<const PassGrid* const> slices, const HeadingOptions& options);
  // Why: the lean graph of the current tables, started at `start` in `start_slice`.
  LeanGraph graph(std::span<const PassGrid* const> slices, std::uint32_t start, int start_slice,
                  std::uint32_t end) const;
  // Why: the robot's turns where it stands, before it moves (the body's own room, the nearest
  // way round): per move slot the cost of reaching it from lg.start_slice, or infinity.
  static void start_turns(const LeanGraph& lg, double turn, double* cost);
  Run run_;
  bool shut_in_ = false;  // the last search ended by EnclosureTest
  static constexpr std::uint32_t kFirstTouchPops = 256;  // pops 512 never-written states count for
  std::size_t resident_pages_ = 0;  // pages some search has written (handed out in order)

  std::unique_ptr<double[]> g_;          // per pool state: cells, best cost from the start
  std::unique_ptr<std::uint8_t[]> meta_; // per pool state: parent (low 4 bits) | kSeen | kClosed
  std::size_t budget_ = 0;               // states in g_ and meta_
  std::vector<TileEntry> tiles_;         // per tile of the stored grid
  std::vector<PageOrigin> origin_;       // per page (budget_ / kTileCells at most)
  int tiles_x_ = 0;                      // tiles per stored row
  int page_shift_ = 0;                   // log2 of states per page (this search)
  int slot_bits_ = 0;                    // log2 of move slots per page (this search)
  int group_shift_ = 0;                  // log2 of pages (slot groups) per tile (this search)
  std::size_t pages_ = 0;                // pages the pool holds (this search)
  std::size_t used_ = 0;                 // pages taken (this search)
  IndexedHeap open_;           // open list for very uneven costs
  std::vector<CellPose> path_; // last path, start first
  std::uint16_t gen_ = 0;      // generation stamp
  std::vector<const std::uint8_t*> cls_of_;  // per slice: its cell classes (this search)
  std::vector<std::uint8_t> allowed_;        // per slice: allowed move bits (this search)
  std::vector<int> move_slice_;              // per move slot: its slice (this search)
  std::vector<int> slot_of_;                 // per slice: its move slot, or -1 (this search)
  BucketRing ring_;            // open list when edge costs allow (else open_)
  EnclosureTest enclosure_;    // the shut-in proof
  std::vector<double> end_extra_;  // per move slot: cost added on reaching the end cell (backward:
                                   // the robot's turn there from its slice; forward: 0)
  std::vector<double> seed_cost_;  // per move slot: the start's turn to it in the body's room, or inf
  // The kept tree (backward searches; heading_tree.cpp).
  bool kept_ = false;              // the last search was a backward one that ended keeping its tree
  double bound_ = 0.0;             // cells: the robot's cost when the tree was made (inf: exhausted)
  double settle_ = 0.0;            // cells: keys at most this are settled (inf: exhausted)
  double robot_h_ = 0.0;           // cells: the goal field at the robot's cell (toward_robot())
  std::vector<double> slot_turn_;  // per move slot: cells, the least turning from the robot's slice
  std::uint32_t goal_cell_ = 0;    // stored index of the goal cell (the tree's seeds)
  std::unique_ptr<std::uint8_t[]> memo_;  // per pool state: epoch << 1 | valid (tree_valid())
  std::uint8_t epoch_ = 0;         // tree_valid()'s memo generation (7 bits)
  std::vector<std::uint32_t> chain_;  // tree_valid()'s walk
};

// Why: which of the 8 moves a slice allows under a motion model (bit m set = move m allowed).
std::uint8_t allowed_moves(int slice, int slices, MotionModel motion);

}  // namespace robuter::plan
