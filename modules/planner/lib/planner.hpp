// SPDX-License-Identifier: GPL-3.0-or-later
// The planner facade: owns a map, its footprint C-space layers and the searches; plans poses.
#pragma once

#include <cstdint>
#include <vector>

#include "modules/planner/lib/cost_field.hpp"
#include "modules/planner/lib/cspace.hpp"
#include "modules/planner/lib/footprint.hpp"
#include "modules/planner/lib/geometry.hpp"
#include "modules/planner/lib/grid_search.hpp"
#include "modules/planner/lib/heading_search.hpp"
#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/planner/lib/pass_grid.hpp"
#include "modules/planner/lib/plan_result.hpp"
#include "modules/planner/lib/slice_bits.hpp"
#include "modules/planner/lib/turn_room.hpp"

namespace robuter::plan {

// The robot's shape as the planner sees it.
enum class FootprintKind : std::uint8_t {
  Disc,       // the thesis: obstacles expanded by a radius, orientation ignored
  Rectangle,  // the Robuter: a rectangle with heading, (x, y, heading slice) search
};

// Everything that shapes a plan.
struct PlannerConfig {
  FootprintKind footprint = FootprintKind::Disc;  // robot model
  double radius = 0.30;                           // m, disc radius (Disc)
  RectangleFootprint rectangle{};                 // m, body (Rectangle)
  int heading_slices = 16;                        // slices over a half turn (Rectangle); the
                                                  // layers and the search hold twice as many,
                                                  // over the full turn (slices())
  MotionModel motion = MotionModel::Aligned;      // moves within a slice (Rectangle)
  double rotation_cost = 0.30;                    // m of path per rad turned in place (Rectangle)
  double turn_clearance = 0.0;                    // m, extra room all round the body needed to
                                                  // turn in place (Rectangle; 0 = as translating)
  SearchMode mode = SearchMode::Optimal;          // Disc: Optimal or the thesis' Bfs
  double unknown_cost = 1.0;                      // multiplier (>= 1) on unknown cells; 1 = free
  bool incremental = true;                        // Disc+Optimal: keep a cost field to the goal
};

// One point of a plan, in the world.
struct Waypoint {
  CellPose cell;  // cells and heading slice (slice 0 for a disc)
  Pose2 pose;     // m and rad: cell centre; heading = slice heading (Rectangle) or direction
                  // of travel (Disc)
};

// Owns the map and everything derived from it. All buffers are sized by set_map(); plan() and
// map updates do not allocate afterwards. Map changes (integrate_beam, mark_*) made through
// map() are folded into the layers and the cost field at the next plan() (or sync()).
class Planner {
 public:
  explicit Planner(const PlannerConfig& config = {});

  // Why: adopt a map and build the C-space layers (the allocation point).
  void set_map(const OccupancyMap& map);
  OccupancyMap& map() { return map_; }
  const OccupancyMap& map() const { return map_; }
  const PlannerConfig& config() const { return cfg_; }

  // Why: fold the map's logged changes into the layers and the cost field (deferred while a
  // prepare_step() or a plan_step() is under way). Returns the cells it freed (occupied no
  // longer): a sync's costly part (each layer re-tests the blocked cells whose footprint covered
  // one: ~1 ms per cell over the default map's 65 layers; new obstacles and free <-> unknown
  // changes cost a few µs a cell), which a caller with a time budget keeps apart from other steps.
  std::uint32_t sync();

  // Why: the window moves by whole cells (docs/PLANNER.md, "The window"): the map's counts move
  // in place (OccupancyMap::shift) and the shared occupancy table is retaken, in one call; the
  // layers are then stale until rebuild_step() has returned true. No allocation. Between the two,
  // the map must not change and nothing may sync, prepare or plan.
  void shift_map(int dx, int dy);
  // Why: known structure (a place graph's walls, places/wall_raster.hpp) the map takes in
  // set_map() and after each shift, before the layers are built from it: every unknown cell the
  // structure holds occupied becomes occupied (at the most hits). Null: none. Set before
  // set_map(); `structure` must outlive the planner and have the map's resolution and cell alignment.
  void set_structure(const OccupancyMap* structure) { structure_ = structure; }
  // Why: cells remembered from an earlier run (saved place grids, places/place_grid.hpp), taken
  // like the structure but after it and weaker: an unknown cell the memory holds occupied
  // becomes occupied at the threshold (one miss clears it: furniture moves), one it holds free
  // becomes free. Null: none. Same conditions as set_structure().
  void set_memory(const OccupancyMap* memory) { memory_ = memory; }
  // Why: rebuilds at most `layers` C-space layers after shift_map() (the turn layers and the
  // relaxation count as layers), so that a caller with a time budget spreads the rebuild over
  // several steps; true once every layer is rebuilt (at once when none is pending).
  bool rebuild_step(int layers);
  bool rebuilding() const { return rebuild_next_ >= 0; }

  // Why: a plan's largest fixed cost is the goal's cost field (a Dijkstra over the whole map:
  // the heuristic of the rectangle search, the path itself for the incremental disc); a caller
  // with a time budget pays it here, in a step of its own, so that plan() only searches.
  // Folds pending map changes first. No effect for a goal off the map or a one-shot search.
  void prepare(Point2 goal);
  // Why: prepare() in steps of at most `max_cells` settled cells, for a caller whose activation
  // must stay short (the field of a 320 x 320 window of unknown cells settles ~100 k cells):
  // true once the field for `goal` is complete (or none is needed). While steps are pending,
  // sync() defers (the map keeps its logged changes; the field's grid must not change under it)
  // and the next plan() completes the field at once; a new goal starts it again.
  bool prepare_step(Point2 goal, std::uint32_t max_cells);

  // Why: plan from a pose to a point (world frame); the path is then in waypoints().
  // PlanResult lengths and costs are in cells (multiply by resolution for metres).
  PlanResult plan(const Pose2& start, Point2 goal);

  // Why: plan() in steps, for a caller whose activation must stay short: each call pops at most
  // `max_pops` states of the (x, y, heading) search and returns true once the plan has ended
  // (`out` then holds what plan() returns, and waypoints() the path). The first call folds the
  // map's changes and needs the goal's field (prepare_step() first, or it is made at once);
  // until the last, sync() defers (the layers must hold still under the search). A call with
  // another start or goal starts again. The disc plans at once.
  bool plan_step(const Pose2& start, Point2 goal, std::uint32_t max_pops, PlanResult& out);
  // Why: drop a prepare_step() or plan_step() under way (the caller moved on); syncs resume.
  void cancel_steps();
  bool stepping() const { return field_.pending() || (active_->pending() && !active_->growing()); }
  // Why: a search begun by plan_step() and not ended (the next plan_step() continues it).
  bool searching() const { return active_->pending() && !active_->growing(); }
  // Why: plan_step() towards `goal` would find its heuristic field made (no whole field to
  // compute in that step): none needed, or ready for the goal's cell and no repair waiting.
  bool field_ready(Point2 goal) const;
  // Why: fields computed whole inside prepare() or a plan's first step, since set_map(): a
  // caller with a time budget (the module) makes them in steps and keeps this at 0.
  std::uint32_t whole_fields() const { return whole_fields_; }
  // Why: the kept tree (docs/PLANNER.md, "The kept tree") grows after a plan made without it, in
  // steps of at most `max_pops` states, while the robot drives: true once it is complete (or none
  // is growing). Syncs go on meanwhile (new obstacles leave a growing tree sound; a cell made
  // cheaper drops it), and a plan drops a tree still growing. A replan for the same goal after
  // syncs that made nothing cheaper then searches only where the tree broke.
  bool grow_tree_step(std::uint32_t max_pops);
  void grow_tree();  // grow_tree_step() unbounded
  bool tree_growing() const { return tree_.growing(); }
  bool tree_kept() const { return tree_.kept(); }
  // Why: figures: states the tree expanded (so far, while it grows), and pages it took.
  std::uint32_t tree_states() const { return tree_.expanded_so_far(); }
  std::size_t tree_pages() const { return tree_.pages_used(); }
  std::size_t tree_page_states() const { return tree_.page_states(); }

  const std::vector<Waypoint>& waypoints() const { return waypoints_; }
  // Why: pictures show the expanded obstacles of a slice (slice 0 for a disc).
  const PassGrid& expanded(int slice = 0) const;
  // Why: the follower and the route ask whether turning in place at a cell is allowed in a
  // slice (the slice's grown body is clear there; the body itself when no turn clearance is
  // configured). False off the map.
  bool can_turn(Cell c, int slice) const;
  // Why: a turn in place where the robot stands (the follower's via, final and exploring turns)
  // measured from its pose (turn_room.hpp; it errs only towards refusing): the body keeps
  // more than turn_clearance, rounded, from every occupied cell at every heading from
  // pose.heading to target (rad). Finer than can_turn's cells and square-grown bodies, which
  // forbid every turn in a 2.10 m corridor where the body's corners pass 0.27 m from the walls
  // (docs/PLANNER.md, "A turn where the robot stands"). Rectangle only; false off the map.
  bool can_turn_at(const Pose2& pose, double target) const;
  // Why: tests compare the turn layers (one bit per slice per cell; empty without clearance).
  const SliceBits& turn_room() const { return turn_room_; }
  int slices() const { return static_cast<int>(layers_.size()); }
  // Why: the rectangle's slices over the full turn (the body is not symmetric under a half
  // turn: its centre is ahead of the axle, the pose).
  int full_turn_slices() const { return 2 * cfg_.heading_slices; }
  const CostField& field() const { return field_; }

 private:
  void ensure_field(const PassGrid& grid, Cell goal);
  const PassGrid* field_grid(Cell goal) const;  // the grid the goal's field is on, or null
  HeadingOptions heading_options() const;       // the rectangle search's options
  void fill_waypoints_2d(const std::vector<Cell>& cells);
  void fill_waypoints_3d(const std::vector<CellPose>& cells);
  void stamp_structure();  // set_structure()'s, then set_memory()'s cells onto map_ (no layer follows: callers rebuild)

  PlannerConfig cfg_;
  CostModel costs_;                     // from cfg_.unknown_cost
  OccupancyMap map_;                    // the world model
  std::vector<FootprintMask> masks_;    // per layer, for masks_resolution_
  FootprintMask relaxation_mask_;       // inscribed disc (Rectangle)
  double masks_resolution_ = 0.0;       // m per cell the masks were made for
  CSpaceStack cspace_;                  // the occupancy and marks every layer shares
  std::vector<CSpaceLayer> layers_;     // Disc: 1 layer; Rectangle: one per heading slice
  CSpaceLayer relaxation_;              // Rectangle: inscribed-disc layer (heuristic field)
  std::vector<const PassGrid*> slice_grids_;  // pointers to layers_' grids
  std::vector<FootprintMask> turn_masks_;     // Rectangle with turn_clearance: grown body per slice
  std::vector<CSpaceLayer> turn_layers_;      // per slice: the grown body's mask, kept as bits
  SliceBits turn_room_;                       // bit k set: turning at the cell blocked in slice k
  TurnEnvelope turn_envelope_;                // Rectangle: the body grown by turn_clearance, per bearing
  std::vector<ClassChange> field_changes_;    // changes of the field's grid in one sync
  CostField field_;                     // cost to the goal on the field grid
  bool field_ready_ = false;            // field_ matches the current goal and grid
  std::uint32_t whole_fields_ = 0;      // fields computed at once (ensure_field), count
  bool field_deferred_ = false;         // Rectangle: field_ lacks new obstacles (still admissible)
  GridSearch grid_search_;              // one-shot 2D searches
  // The (x, y, slice) searches from the robot: a plan without the tree runs in tree_ (whose
  // pages then hold the tree that grows after it: memory is the larger of the two, not their
  // sum), a plan with the tree in heading_search_ (it reads tree_; it searches only where the
  // tree broke, a few pages).
  HeadingSearch heading_search_;        // the search with the kept tree
  HeadingSearch* active_ = &heading_search_;  // the search of the plan under way (or the last)
  // The kept tree (Rectangle; docs/PLANNER.md, "The kept tree"): a search from the goal whose
  // exact costs survive new obstacles and the robot's moves; made again for a new goal or after
  // a sync that made a cell cheaper.
  HeadingSearch tree_;                  // the tree
  Cell tree_goal_{};                    // cells: the goal it was made for
  Cell tree_robot_{};                   // cells: the robot's cell it was made towards
  bool step_tree_ = false;              // the plan under way searches with the kept tree
  // Why: plan_step()'s search, resumed; a plan made without the tree then starts the tree growing.
  bool continue_plan(std::uint32_t max_pops, PlanResult& out);
  std::vector<Cell> cells_;             // 2D path buffer
  std::vector<Waypoint> waypoints_;     // last plan
  const OccupancyMap* structure_ = nullptr;  // known structure the window takes as it moves
  const OccupancyMap* memory_ = nullptr;     // cells remembered from an earlier run, taken after it
  int rebuild_next_ = -1;               // next layer to rebuild after shift_map (-1: none)
  CellPose step_start_{};               // cells, slice: the start of a plan_step() search
  Cell step_goal_{};                    // cells: its goal
};

}  // namespace robuter::plan
