// SPDX-License-Identifier: GPL-3.0-or-later
// Reverse Dijkstra from the goal with subtree invalidation for incremental repairs.
#include "modules/planner/lib/cost_field.hpp"

#include <algorithm>

namespace robuter::plan {

void CostField::reserve(int width, int height) {
  const auto stored = static_cast<std::size_t>(width + 2) * static_cast<std::size_t>(height + 2);
  if (dist_.size() < stored) {
    dist_.assign(stored, kInfinity);
    next_.assign(stored, kNoMove);
    in_heap_.assign(stored, 0);
    reset_.assign(stored, 0);
    work_.reserve(stored);
  }
  heap_.reserve(stored);
  ring_.reserve(stored);
}

bool CostField::compute(const PassGrid& grid, Cell goal, const CostModel& costs) {
  begin(grid, goal, costs);
  step(~std::uint32_t{0});
  return grid.contains(goal) && grid.at(goal) != kBlocked;
}

void CostField::begin(const PassGrid& grid, Cell goal, const CostModel& costs) {
  reserve(grid.width, grid.height);
  grid_ = &grid;
  costs_ = costs;
  table_ = costs.table();
  mt_ = MoveTable(grid.stride);
  goal_ = goal;
  std::fill(dist_.begin(), dist_.begin() + static_cast<std::ptrdiff_t>(grid.stored()), kInfinity);
  std::fill(next_.begin(), next_.begin() + static_cast<std::ptrdiff_t>(grid.stored()), std::uint8_t{kNoMove});
  // A computation dropped half-way (cancel()) leaves cells marked as queued.
  std::fill(in_heap_.begin(), in_heap_.begin() + static_cast<std::ptrdiff_t>(grid.stored()), std::uint8_t{0});
  heap_.clear();
  settled_ = 0;
  invalidated_ = 0;
  pending_ = false;
  if (!grid.contains(goal)) {
    goal_index_ = 0;  // a border cell: always blocked, never seeded
    return;
  }
  goal_index_ = grid.index(goal);
  // One seed: Dijkstra's keys stay within two edges of the lowest, so the bucket ring fits
  // (label-correcting: a cell improved after its pop is queued again, so the result is exact).
  use_ring_ = ring_.reset(kBucketWidth, kSqrt2 * std::max(1.0, costs_.unknown_cost), 0.0);
  seed(goal_index_);
  pending_ = true;
}

bool CostField::step(std::uint32_t max_settled) {
  if (!pending_) return true;
  if (run(max_settled)) {
    pending_ = false;
    use_ring_ = false;
  }
  return !pending_;
}

double CostField::cost(Cell c) const {
  if (!grid_ || !grid_->contains(c)) return kInfinity;
  return dist_[grid_->index(c)];
}

// Why: the move m from u is usable (both ends traversable, no corner cutting).
bool CostField::edge_ok(std::uint32_t u, int m) const {
  const std::uint8_t* cls = grid_->cls.data();
  const std::uint32_t v = u + static_cast<std::uint32_t>(mt_.step[m]);
  if (cls[u] == kBlocked || cls[v] == kBlocked) return false;
  if (m < 4) return true;
  return cls[u + static_cast<std::uint32_t>(mt_.side_a[m])] != kBlocked &&
         cls[u + static_cast<std::uint32_t>(mt_.side_b[m])] != kBlocked;
}

// Why: queue v with key d, or lower its key (old = the key it is queued with = its old dist).
void CostField::push_or_lower(std::uint32_t v, double old, double d) {
  if (use_ring_) {
    if (in_heap_[v]) {
      ring_.lower_key(v, old, d);
    } else {
      in_heap_[v] = 1;
      ring_.push(v, d);
    }
    return;
  }
  if (in_heap_[v]) {
    heap_.decrease(v, d, 0.0f);
  } else {
    in_heap_[v] = 1;
    heap_.push(v, d, 0.0f);
  }
}

// Why: a cell's best value from its current neighbours (the goal is always 0); queued if finite.
void CostField::seed(std::uint32_t v) {
  const std::uint8_t* cls = grid_->cls.data();
  if (cls[v] == kBlocked) return;
  if (v == goal_index_) {
    const double old = dist_[v];
    dist_[v] = 0.0;
    next_[v] = kNoMove;
    push_or_lower(v, old, 0.0);
    return;
  }
  const double old = dist_[v];
  double best = old;
  int best_m = -1;
  for (int m = 0; m < 8; ++m) {
    const std::uint32_t y = v + static_cast<std::uint32_t>(mt_.step[m]);
    if (dist_[y] == kInfinity || !edge_ok(v, m)) continue;
    const double d = dist_[y] + table_[m][cls[v]][cls[y]];
    if (d < best) {
      best = d;
      best_m = m;
    }
  }
  if (best_m >= 0) {
    dist_[v] = best;
    next_[v] = static_cast<std::uint8_t>(best_m);
  }
  if (dist_[v] != kInfinity) push_or_lower(v, old, dist_[v]);
}

// Why: Dijkstra relaxation of u's neighbours (the graph is symmetric).
void CostField::relax_from(std::uint32_t u) {
  const std::uint8_t* cls = grid_->cls.data();
  const double du = dist_[u];
  for (int m = 0; m < 8; ++m) {
    if (!edge_ok(u, m)) continue;
    const std::uint32_t v = u + static_cast<std::uint32_t>(mt_.step[m]);
    const double d = du + table_[m][cls[u]][cls[v]];
    if (d < dist_[v]) {
      const double old = dist_[v];
      dist_[v] = d;
      next_[v] = static_cast<std::uint8_t>(opposite_move(m));
      push_or_lower(v, old, d);
    }
  }
}

bool CostField::run(std::uint32_t max_settled) {
  for (std::uint32_t n = 0;; ++n) {
    if (n == max_settled) return use_ring_ ? ring_.empty() : heap_.empty();
    std::uint32_t u;
    if (use_ring_) {
      if (ring_.empty()) return true;
      u = ring_.pop();
    } else {
      if (heap_.empty()) return true;
      u = heap_.pop().node;
    }
    in_heap_[u] = 0;
    ++settled_;
    relax_from(u);
  }
}

// Why: every cell whose route to the goal passes through `root` loses its value.
void CostField::invalidate_subtree(std::uint32_t root) {
  if (reset_[root]) return;
  std::size_t i = work_.size();
  reset_[root] = 1;
  work_.push_back(root);
  for (; i < work_.size(); ++i) {
    const std::uint32_t x = work_[i];
    dist_[x] = kInfinity;
    next_[x] = kNoMove;
    for (int m = 0; m < 8; ++m) {
      const std::uint32_t y = x + static_cast<std::uint32_t>(mt_.step[m]);
      const std::uint8_t k = next_[y];
      if (reset_[y] || k == kNoMove) continue;
      if (y + static_cast<std::uint32_t>(mt_.step[k]) == x) {
        reset_[y] = 1;
        work_.push_back(y);
      }
    }
  }
}

void CostField::update(std::span<const ClassChange> changes) {
  if (!grid_ || pending_) return;
  const std::uint8_t* cls = grid_->cls.data();
  const std::array<double, 3> mult = {kInfinity, 1.0, std::max(1.0, costs_.unknown_cost)};
  settled_ = 0;
  work_.clear();
  // 1. Worse cells: reset their subtrees, and for a newly blocked cell also the subtrees of
  //    neighbours whose next move was a diagonal passing by it.
  for (const ClassChange& ch : changes) {
    const std::uint32_t c = ch.index;
    if (!(mult[cls[c]] > mult[ch.before])) continue;
    if (dist_[c] != kInfinity) invalidate_subtree(c);
    if (cls[c] != kBlocked) continue;
    for (int m = 0; m < 8; ++m) {
      const std::uint32_t n = c + static_cast<std::uint32_t>(mt_.step[m]);
      const std::uint8_t k = next_[n];
      if (k == kNoMove || k < 4) continue;
      if (n + static_cast<std::uint32_t>(mt_.side_a[k]) == c ||
          n + static_cast<std::uint32_t>(mt_.side_b[k]) == c)
        invalidate_subtree(n);
    }
  }
  invalidated_ = static_cast<std::uint32_t>(work_.size());
  // 2. Seeds: reset cells from their unaffected neighbours.
  for (std::uint32_t x : work_) seed(x);
  // 3. Better cells: their own value, and their neighbours (cheaper or new diagonal edges).
  for (const ClassChange& ch : changes) {
    const std::uint32_t c = ch.index;
    if (!(mult[cls[c]] < mult[ch.before])) continue;
    seed(c);
    for (int m = 0; m < 8; ++m) {
      const std::uint32_t n = c + static_cast<std::uint32_t>(mt_.step[m]);
      if (cls[n] != kBlocked && dist_[n] != kInfinity) push_or_lower(n, dist_[n], dist_[n]);
    }
  }
  for (std::uint32_t x : work_) reset_[x] = 0;
  run(~std::uint32_t{0});
}

PlanResult CostField::path_from(Cell start, std::vector<Cell>& path) const {
  PlanResult r;
  path.clear();
  if (!grid_) return r;
  if (!grid_->contains(start)) return r.status = PlanStatus::StartOutside, r;
  if (!grid_->contains(goal_)) return r.status = PlanStatus::GoalOutside, r;
  if (grid_->at(start) == kBlocked) return r.status = PlanStatus::StartBlocked, r;
  if (grid_->at(goal_) == kBlocked) return r.status = PlanStatus::GoalBlocked, r;
  std::uint32_t v = grid_->index(start);
  if (dist_[v] == kInfinity) return r;  // Unreachable
  int orth = 0;
  int diag = 0;
  path.push_back(start);
  for (std::size_t guard = grid_->stored(); v != goal_index_ && guard > 0; --guard) {
    const int m = next_[v];
    (m < 4 ? orth : diag) += 1;
    v += static_cast<std::uint32_t>(mt_.step[m]);
    path.push_back(grid_->cell(v));
  }
  if (v != goal_index_) return path.clear(), r;  // broken pointers: cannot happen, never loop
  r.status = PlanStatus::Found;
  r.cost = dist_[grid_->index(start)];
  r.length = static_cast<double>(orth) + kSqrt2 * static_cast<double>(diag);
  r.expanded = 0;
  return r;
}

}  // namespace robuter::plan
