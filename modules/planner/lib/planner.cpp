// SPDX-License-Identifier: GPL-3.0-or-later
// Planner facade: layers from the map, the right search per footprint, incremental upkeep.
#include "modules/planner/lib/planner.hpp"

#include <cmath>

namespace robuter::plan {

Planner::Planner(const PlannerConfig& config)
    : cfg_(config), turn_envelope_(config.rectangle, config.turn_clearance) {
  if (cfg_.heading_slices < 1) cfg_.heading_slices = 1;
  costs_.unknown_cost = cfg_.unknown_cost < 1.0 ? 1.0 : cfg_.unknown_cost;
  set_map(OccupancyMap(MapGeometry{1, 1, 0.05, {}}));
}

void Planner::set_map(const OccupancyMap& map) {
  map_ = map;
  stamp_structure();
  map_.clear_changes();
  const double res = map_.resolution();
  if (res != masks_resolution_) {  // masks depend on the resolution only: made once
    masks_resolution_ = res;
    masks_.clear();
    if (cfg_.footprint == FootprintKind::Disc) masks_.push_back(disc_mask(cfg_.radius, res));
    else masks_ = rectangle_slices(cfg_.rectangle, res, full_turn_slices());
    relaxation_mask_ = disc_mask(inscribed_radius(cfg_.rectangle), res);
    turn_masks_.clear();
    if (cfg_.footprint == FootprintKind::Rectangle && cfg_.turn_clearance > 0.0) {
      RectangleFootprint grown = cfg_.rectangle;
      grown.margin += cfg_.turn_clearance;
      turn_masks_ = rectangle_slices(grown, res, full_turn_slices());
    }
  }
  cspace_.reset(map_);
  layers_.resize(masks_.size());
  for (std::size_t k = 0; k < masks_.size(); ++k) layers_[k].build(cspace_, map_, masks_[k]);
  if (cfg_.footprint == FootprintKind::Rectangle) relaxation_.build(cspace_, map_, relaxation_mask_);
  slice_grids_.clear();
  for (const CSpaceLayer& l : layers_) slice_grids_.push_back(&l.grid());
  turn_layers_.resize(turn_masks_.size());
  turn_room_.resize(turn_masks_.empty() ? 0 : map_.width(), turn_masks_.empty() ? 0 : map_.height(),
                    static_cast<int>(turn_masks_.size()));
  for (std::size_t k = 0; k < turn_masks_.size(); ++k)
    turn_layers_[k].build_bits(cspace_, map_, turn_masks_[k], turn_room_, static_cast<int>(k));
  const int w = map_.width(), h = map_.height();
  field_changes_.clear();
  field_changes_.reserve(map_.cell_count());
  field_.reserve(w, h);
  cancel_steps();
  field_ready_ = false;
  // Each footprint reserves only the search it uses (the rectangle never runs the 2D one).
  tree_.forget();
  if (cfg_.footprint == FootprintKind::Rectangle) {
    heading_search_.reserve(w, h, full_turn_slices());
    tree_.reserve(w, h, full_turn_slices());  // plans without the tree run here too
  } else {
    grid_search_.reserve(w, h);
    cells_.reserve(map_.cell_count() + 1);
  }
  waypoints_.reserve(2 * map_.cell_count() + layers_.size());
}

std::uint32_t Planner::sync() {
  if (stepping()) return 0;  // prepare_step() or plan_step() under way: their grids hold still
  const auto changed = map_.changes();
  if (changed.empty()) return 0;
  const bool rect = cfg_.footprint == FootprintKind::Rectangle;
  field_changes_.clear();
  const std::uint32_t freed = cspace_.begin_sync(map_, changed);
  for (std::size_t k = 0; k < layers_.size(); ++k)
    layers_[k].update(cspace_, map_, changed, !rect && k == 0 ? &field_changes_ : nullptr);
  for (std::size_t k = 0; k < turn_layers_.size(); ++k)
    turn_layers_[k].update_bits(cspace_, map_, changed, turn_room_, static_cast<int>(k));
  // The rectangle's field is only the search's heuristic: after a sync that made nothing
  // cheaper (new obstacles; free <-> unknown when both cost the same) the field as it was is
  // still admissible and consistent, so its repair waits (docs/PLANNER.md, "Shut in"); a sync
  // that makes a cell cheaper while a repair waits drops the field (made again at the next plan).
  // The kept tree likewise holds exact costs only while costs have not fallen.
  bool cheaper = false;
  for (const std::uint32_t c : rect && (field_ready_ || tree_.kept() || tree_.growing()) ? changed : std::span<const std::uint32_t>{}) {
    const CellChange kind = cspace_.kind(c);
    cheaper = cheaper || kind == kLowered || (kind == kRelabelled && costs_.unknown_cost != 1.0);
  }
  if (cheaper) {  // a tree kept or growing no longer bounds the costs from below
    if (tree_.growing()) tree_.cancel();
    tree_.forget();
  }
  const bool repair = cheaper && !field_deferred_;  // the rectangle's field repaired now
  if (rect) relaxation_.update(cspace_, map_, changed, repair ? &field_changes_ : nullptr);
  cspace_.end_sync(changed);
  if (field_ready_) {
    if (!rect || repair) {
      field_.update(field_changes_);
    } else if (!cheaper) {
      field_deferred_ = true;
    } else {  // cheaper, with new obstacles not folded in: made again at the next plan
      field_ready_ = false;
      field_deferred_ = false;
    }
  }
  map_.clear_changes();
  return freed;
}

// Known structure takes the most hits a cell holds (OccupancyMap::kMaxCount), so that the ring's
// misses through a wall's face cells (an echo just behind them) do not wear it away. The grids
// share cell boundaries (same resolution, origins on multiples of it): a whole-cell offset.
// Remembered cells come after it, only where the map and the structure leave a cell unknown.
void Planner::stamp_structure() {
  const auto stamp = [&](const OccupancyMap& from, auto&& take) {
    const Cell o = from.cell_of(map_.center({0, 0}));  // the source's cell under the map's (0, 0)
    for (int y = 0; y < map_.height(); ++y) {
      const int sy = y + o.y;
      if (sy < 0 || sy >= from.height()) continue;
      for (int x = 0; x < map_.width(); ++x) {
        const Cell s{x + o.x, sy};
        if (s.x < 0 || s.x >= from.width() || from.state(s) == CellState::Unknown) continue;
        if (map_.state({x, y}) == CellState::Unknown) take(Cell{x, y}, from.state(s));
      }
    }
  };
  if (structure_ != nullptr)
    stamp(*structure_, [&](Cell c, CellState s) {
      if (s == CellState::Occupied) map_.set_count(c, OccupancyMap::kMaxCount);
    });
  if (memory_ != nullptr)
    stamp(*memory_, [&](Cell c, CellState s) {
      if (s == CellState::Occupied) map_.mark_occupied(c);
      else map_.mark_free(c);
    });
}

void Planner::shift_map(int dx, int dy) {
  map_.shift(dx, dy);
  stamp_structure();
  map_.clear_changes();  // the layers are retaken from the map as it now is
  cspace_.reset(map_);  // same size: the table and marks are refilled, not reallocated
  cancel_steps();
  field_ready_ = false;
  tree_.forget();
  waypoints_.clear();
  rebuild_next_ = 0;
}

// Layers in order: the heading slices, the turn layers, then the relaxation (rectangle).
bool Planner::rebuild_step(int layers) {
  if (rebuild_next_ < 0) return true;
  const int slices = static_cast<int>(layers_.size()), turns = static_cast<int>(turn_layers_.size());
  const int total = slices + turns + (cfg_.footprint == FootprintKind::Rectangle ? 1 : 0);
  for (int n = 0; n < layers && rebuild_next_ < total; ++n, ++rebuild_next_) {
    const int k = rebuild_next_;
    if (k < slices) layers_[static_cast<std::size_t>(k)].rebuild(cspace_, map_);
    else if (k < slices + turns)  // turn layers are bits (turn_room_); their grid() is empty
      turn_layers_[static_cast<std::size_t>(k - slices)].rebuild_bits(cspace_, map_, turn_room_, k - slices);
    else relaxation_.rebuild(cspace_, map_);
  }
  if (rebuild_next_ < total) return false;
  rebuild_next_ = -1;
  return true;
}

const PassGrid& Planner::expanded(int slice) const {
  const int k = slice < 0 || slice >= slices() ? 0 : slice;
  return layers_[static_cast<std::size_t>(k)].grid();
}

bool Planner::can_turn(Cell c, int slice) const {
  if (!map_.contains(c)) return false;
  const int k = slice < 0 || slice >= slices() ? 0 : slice;
  if (turn_layers_.empty()) return layers_[static_cast<std::size_t>(k)].grid().at(c) != kBlocked;
  return !turn_room_.blocked(c, k);
}

bool Planner::can_turn_at(const Pose2& pose, double target) const {
  if (!map_.contains(map_.cell_of({pose.x, pose.y}))) return false;
  return turn_envelope_.turn_is_clear(map_, pose, target);
}

// Why: the cost field is recomputed only when the goal moves; map changes repair it.
void Planner::ensure_field(const PassGrid& grid, Cell goal) {
  if (field_ready_ && field_.goal() == goal) return;
  ++whole_fields_;
  field_.compute(grid, goal, costs_);
  field_ready_ = true;
  field_deferred_ = false;
}

const PassGrid* Planner::field_grid(Cell g) const {
  if (cfg_.footprint == FootprintKind::Rectangle)
    return relaxation_.grid().contains(g) ? &relaxation_.grid() : nullptr;
  if (cfg_.mode == SearchMode::Optimal && cfg_.incremental && layers_[0].grid().contains(g)) return &layers_[0].grid();
  return nullptr;
}

void Planner::cancel_steps() {
  field_.cancel();
  heading_search_.cancel();
  tree_.cancel();  // a tree cut short is not kept
}

void Planner::prepare(Point2 goal) {
  cancel_steps();
  sync();
  const Cell g = map_.cell_of(goal);
  if (const PassGrid* grid = field_grid(g)) ensure_field(*grid, g);
}

bool Planner::field_ready(Point2 goal) const {
  const Cell g = map_.cell_of(goal);
  if (cfg_.footprint != FootprintKind::Rectangle) return true;  // plan() makes what it needs
  const PassGrid* grid = field_grid(g);
  return grid == nullptr || (!field_.pending() && field_ready_ && field_.goal() == g);
}

bool Planner::prepare_step(Point2 goal, std::uint32_t max_cells) {
  if (active_->pending() && !active_->growing()) active_->cancel();  // a field is asked for: any search under way is moot
  const Cell g = map_.cell_of(goal);
  if (field_.pending() && !(field_.goal() == g)) field_.cancel();  // a new goal: start again
  if (!field_.pending()) {
    sync();
    const PassGrid* grid = field_grid(g);
    if (grid == nullptr || (field_ready_ && field_.goal() == g)) return true;
    field_ready_ = false;
    field_deferred_ = false;
    field_.begin(*grid, g, costs_);
  }
  field_ready_ = field_.step(max_cells);
  return field_ready_;
}

bool Planner::plan_step(const Pose2& start, Point2 goal, std::uint32_t max_pops, PlanResult& out) {
  const Cell s = map_.cell_of({start.x, start.y});
  const Cell g = map_.cell_of(goal);
  if (active_->pending() && !active_->growing()) {
    const CellPose sp{s.x, s.y, slice_of_heading(start.heading, full_turn_slices())};
    if (sp == step_start_ && g == step_goal_) return continue_plan(max_pops, out);
    active_->cancel();  // another start or goal: start again
  }
  if (cfg_.footprint != FootprintKind::Rectangle) {
    out = plan(start, goal);
    return true;
  }
  field_.cancel();  // a field still in steps is made at once below, after the sync
  if (tree_.growing()) tree_.cancel();  // a tree still growing is dropped: the plan does not wait for it
  sync();
  waypoints_.clear();
  const int k = slice_of_heading(start.heading, full_turn_slices());
  const PassGrid& relax = relaxation_.grid();
  const CostField* h = nullptr;
  if (relax.contains(g)) {
    ensure_field(relax, g);
    h = &field_;
  }
  step_start_ = CellPose{s.x, s.y, k};
  step_goal_ = g;
  // The kept tree serves while the goal is the same; an exhausted one (the robot could not be
  // reached) only while the robot has not moved either.
  if (tree_.kept() && (!(tree_goal_ == g) || (tree_.kept_bound() == CostField::kInfinity && !(tree_robot_ == s))))
    tree_.forget();
  HeadingSearch* tree = h != nullptr && tree_.kept() ? &tree_ : nullptr;
  step_tree_ = tree != nullptr;
  active_ = tree != nullptr ? &heading_search_ : &tree_;
  if (active_->begin(slice_grids_, step_start_, g, heading_options(), costs_, h,
                     turn_layers_.empty() ? nullptr : &turn_room_, out, tree))
    return true;  // known at once: outside, blocked, unreachable by the relaxation, already there
  if (tree != nullptr && tree_.kept_bound() == CostField::kInfinity) {  // the robot's cell, still shut off
    active_->cancel();
    out = PlanResult{};
    out.status = PlanStatus::Unreachable;
    return true;
  }
  return continue_plan(max_pops, out);
}

bool Planner::continue_plan(std::uint32_t max_pops, PlanResult& out) {
  if (!active_->resume(max_pops, out)) return false;
  if (out.found()) fill_waypoints_3d(active_->path());
  // A plan made without the tree: the tree for its goal starts growing (grow_tree_step()),
  // towards where the robot is now.
  if (!step_tree_ && out.found() && field_ready_ && relaxation_.grid().contains(step_goal_)) {
    tree_.begin_backward(slice_grids_, step_start_, step_goal_, heading_options(), costs_, &field_,
                         turn_layers_.empty() ? nullptr : &turn_room_);
    tree_goal_ = step_goal_;
    tree_robot_ = Cell{step_start_.x, step_start_.y};
  }
  return true;
}

bool Planner::grow_tree_step(std::uint32_t max_pops) {
  if (!tree_.growing()) return true;
  PlanResult r;
  return tree_.resume(max_pops, r);
}

void Planner::grow_tree() {
  while (!grow_tree_step(~std::uint32_t{0})) {
  }
}

HeadingOptions Planner::heading_options() const {
  HeadingOptions opt;
  opt.motion = cfg_.motion;
  opt.rotation_step_cost = cfg_.rotation_cost * (2.0 * kPi / full_turn_slices()) / map_.resolution();
  return opt;
}

PlanResult Planner::plan(const Pose2& start, Point2 goal) {
  cancel_steps();  // a field still in steps is made at once below, after the sync
  PlanResult r;
  if (cfg_.footprint == FootprintKind::Rectangle) {
    plan_step(start, goal, ~std::uint32_t{0}, r);  // nothing under way: one unbounded step
    return r;
  }
  sync();
  waypoints_.clear();
  const Cell s = map_.cell_of({start.x, start.y});
  const Cell g = map_.cell_of(goal);
  const PassGrid& grid = layers_[0].grid();  // the disc's one layer
  if (cfg_.mode == SearchMode::Optimal && cfg_.incremental && grid.contains(g)) {
    const bool fresh = !(field_ready_ && field_.goal() == g);
    ensure_field(grid, g);
    r = field_.path_from(s, cells_);
    r.expanded = fresh ? field_.last_settled() : 0;
  } else {
    r = grid_search_.find(grid, s, g, cfg_.mode, costs_);
    cells_.assign(grid_search_.path().begin(), grid_search_.path().end());
  }
  if (r.found()) fill_waypoints_2d(cells_);
  return r;
}

void Planner::fill_waypoints_2d(const std::vector<Cell>& cells) {
  double heading = 0.0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i + 1 < cells.size())
      heading = std::atan2(static_cast<double>(cells[i + 1].y - cells[i].y),
                           static_cast<double>(cells[i + 1].x - cells[i].x));
    const Point2 p = map_.center(cells[i]);
    waypoints_.push_back({CellPose{cells[i].x, cells[i].y, 0}, Pose2{p.x, p.y, heading}});
  }
}

void Planner::fill_waypoints_3d(const std::vector<CellPose>& cells) {
  for (const CellPose& c : cells) {
    const Point2 p = map_.center({c.x, c.y});
    waypoints_.push_back({c, Pose2{p.x, p.y, slice_heading(c.slice, full_turn_slices())}});
  }
}

}  // namespace robuter::plan
