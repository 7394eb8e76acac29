// SPDX-License-Identifier: GPL-3.0-or-later
// Test-only reference: A* over every (cell, heading slice), one slice per turn step.
#include "tests/planner/reference_heading_search.hpp"

#include <algorithm>
#include <cmath>

#include "modules/planner/lib/footprint.hpp"

namespace robuter::plan {

void ReferenceHeadingSearch::reserve(int width, int height, int slices) {
  const auto stored = static_cast<std::size_t>(width + 2) * static_cast<std::size_t>(height + 2);
  // Every (cell, slice), then one state per slice for the start cell before the robot moves.
  const std::size_t states = (stored + 1) * static_cast<std::size_t>(std::max(slices, 1));
  if (nodes_.size() < states) {
    nodes_.assign(states, Node{0.0, 0, kNoMove, 0});
    gen_ = 0;
  }
  open_.reserve(states);
  ring_.reserve(states);
  path_.reserve(2 * stored + static_cast<std::size_t>(std::max(slices, 1)));
  const auto k = static_cast<std::size_t>(std::max(slices, 1));
  if (cls_of_.size() < k) cls_of_.resize(k, nullptr);
  if (turn_of_.size() < k) turn_of_.resize(k, nullptr);
  if (allowed_.size() < k) allowed_.resize(k, 0);
}

PlanResult ReferenceHeadingSearch::find(std::span<const PassGrid* const> slices, CellPose start, Cell goal,
                               const HeadingOptions& options, const CostModel& costs,
                               const CostField* heuristic,
                               std::span<const PassGrid* const> turn_slices) {
  PlanResult r;
  path_.clear();
  const int k_count = static_cast<int>(slices.size());
  if (k_count == 0) return r;
  const PassGrid& g0 = *slices[0];
  const Cell sc{start.x, start.y};
  if (!g0.contains(sc)) return r.status = PlanStatus::StartOutside, r;
  if (!g0.contains(goal)) return r.status = PlanStatus::GoalOutside, r;
  start.slice = ((start.slice % k_count) + k_count) % k_count;
  if (slices[static_cast<std::size_t>(start.slice)]->at(sc) == kBlocked)
    return r.status = PlanStatus::StartBlocked, r;
  bool goal_free = false;
  for (const PassGrid* g : slices) goal_free = goal_free || g->at(goal) != kBlocked;
  if (!goal_free) return r.status = PlanStatus::GoalBlocked, r;

  reserve(g0.width, g0.height, k_count);
  if (++gen_ == 0) {
    for (Node& n : nodes_) n.stamp = 0;
    gen_ = 1;
  }
  const auto stored = static_cast<std::uint32_t>(g0.stored());
  const auto stride = static_cast<std::uint32_t>(g0.stride);
  const MoveTable mt(g0.stride);
  const auto cost = costs.table();
  std::uint8_t* allowed = allowed_.data();
  const std::uint8_t** cls_of = cls_of_.data();
  const std::uint8_t** turn_of = turn_of_.data();
  const bool own_turns = turn_slices.size() == slices.size();
  for (int k = 0; k < k_count; ++k) {
    allowed[k] = allowed_moves(k, k_count, options.motion);
    cls_of[k] = slices[static_cast<std::size_t>(k)]->cls.data();
    turn_of[k] = own_turns ? turn_slices[static_cast<std::size_t>(k)]->cls.data() : cls_of[k];
  }
  const int tx = goal.x + 1;
  const int ty = goal.y + 1;
  const std::uint32_t t = g0.index(goal);
  auto h_of = [&](std::uint32_t cell) -> double {
    if (heuristic) return heuristic->cost_at(cell);
    return octile(static_cast<int>(cell % stride) - tx, static_cast<int>(cell / stride) - ty);
  };
  const double turn = std::max(options.rotation_step_cost, 0.0);
  Node* nodes = nodes_.data();

  // Open list: the bucket ring when edge costs are bounded enough, else the heap (see
  // BucketRing: with the ring, closed states may be reopened and the loop ends when the lowest
  // bucket reaches the best goal cost; with the heap, when the popped f reaches it).
  const double max_edge = std::max(kSqrt2 * std::max(1.0, costs.unknown_cost), turn);
  const double h0 = h_of(g0.index(sc));
  if (h0 == CostField::kInfinity) return r;  // the relaxation already says unreachable
  const bool use_ring = !options.heap && ring_.reset(kBucketWidth, max_edge, h0);
  open_.clear();
  double best = CostField::kInfinity;
  std::uint32_t reached = 0;

  const std::uint32_t departure = stored * static_cast<std::uint32_t>(k_count);  // first departure state
  const std::uint32_t start_index = g0.index(sc);
  // `before`: the departure copy of the start cell's state (the robot has not moved yet).
  auto relax = [&](std::uint32_t cell, int k, double ng, std::uint8_t how, bool before = false) {
    const std::uint32_t s = before ? departure + static_cast<std::uint32_t>(k) : static_cast<std::uint32_t>(k) * stored + cell;
    Node& n = nodes[s];
    if (n.stamp != gen_) {
      const double h = h_of(cell);
      if (h == CostField::kInfinity) return;  // the relaxation cannot reach the goal from here
      n = Node{ng, gen_, how, 0};
      if (use_ring) ring_.push(s, ng + h);
      else open_.push(s, ng + h, static_cast<float>(h));
    } else if (ng < n.g - 1e-9 && (use_ring || !n.closed)) {
      const double h = h_of(cell);
      if (n.closed) {
        n.closed = 0;  // reopened (ring only): its first expansion came a little early
        ring_.push(s, ng + h);
      } else if (use_ring) {
        ring_.lower_key(s, n.g + h, ng + h);
      } else {
        open_.decrease(s, ng + h, static_cast<float>(h));
      }
      n.g = ng;
      n.parent = how;
    } else {
      return;
    }
    if (cell == t && ng < best) {
      best = ng;
      reached = s;
    }
  };

  relax(start_index, start.slice, 0.0, kNoMove, true);
  for (;;) {
    std::uint32_t s;
    if (use_ring) {
      if (ring_.empty() || ring_.lower() >= best) break;
      s = ring_.pop();
    } else {
      if (open_.empty() || open_.top().key >= best) break;
      s = open_.pop().node;
    }
    Node& ns = nodes[s];
    ns.closed = 1;
    const bool before = s >= departure;
    const std::uint32_t u = before ? start_index : s % stored;
    const int k = before ? static_cast<int>(s - departure) : static_cast<int>(s / stored);
    const double gu = ns.g;
    if (u == t || gu + h_of(u) >= best) continue;
    ++r.expanded;
    const std::uint8_t* cls = cls_of[k];
    const std::uint8_t cu = cls[u];
    const std::uint8_t bits = allowed[k];
    for (int m = 0; m < 8; ++m) {
      if (!(bits & (1u << m))) continue;
      const std::uint32_t v = u + static_cast<std::uint32_t>(mt.step[m]);
      const std::uint8_t cv = cls[v];
      if (cv == kBlocked) continue;
      if (m >= 4 && (cls[u + static_cast<std::uint32_t>(mt.side_a[m])] == kBlocked ||
                     cls[u + static_cast<std::uint32_t>(mt.side_b[m])] == kBlocked))
        continue;
      relax(v, k, gu + cost[m][cu][cv], static_cast<std::uint8_t>(before ? kFromDeparture + m : m));
    }
    if (k_count > 1) {
      const int up = (k + 1) % k_count;
      const int down = (k + k_count - 1) % k_count;
      // The current slice is free at u (tight); turning may ask for more room, except where
      // the robot stands before it moves: there the body's own room is enough (it may have
      // stopped close to something, and must be able to turn away).
      const std::uint8_t* const* room = own_turns && !before ? turn_of : cls_of;
      const bool here = room[k][u] != kBlocked;
      if (here && room[up][u] != kBlocked && cls_of[up][u] != kBlocked) relax(u, up, gu + turn, 8, before);
      if (here && down != up && room[down][u] != kBlocked && cls_of[down][u] != kBlocked)
        relax(u, down, gu + turn, 9, before);
    }
  }
  const bool found = best != CostField::kInfinity;
  if (!found) return r;  // Unreachable

  // Walk back from the goal state.
  int orth = 0;
  int diag = 0;
  std::uint32_t s = reached;
  r.cost = nodes[s].g;
  for (;;) {
    const bool before = s >= departure;
    const std::uint32_t u = before ? start_index : s % stored;
    const int k = before ? static_cast<int>(s - departure) : static_cast<int>(s / stored);
    const Cell c = g0.cell(u);
    path_.push_back({c.x, c.y, k});
    int p = nodes[s].parent;
    if (p == kNoMove) break;
    const bool from_departure = p >= kFromDeparture;
    if (from_departure) p -= kFromDeparture;
    if (p < 8) {
      (p < 4 ? orth : diag) += 1;
      s = from_departure ? departure + static_cast<std::uint32_t>(k)
                         : static_cast<std::uint32_t>(k) * stored + (u - static_cast<std::uint32_t>(mt.step[p]));
    } else {
      const int from = p == 8 ? (k + k_count - 1) % k_count : (k + 1) % k_count;
      s = before ? departure + static_cast<std::uint32_t>(from) : static_cast<std::uint32_t>(from) * stored + u;
    }
  }
  std::reverse(path_.begin(), path_.end());
  r.status = PlanStatus::Found;
  r.length = static_cast<double>(orth) + kSqrt2 * static_cast<double>(diag);
  return r;
}

}  // namespace robuter::plan
