// SPDX-License-Identifier: GPL-3.0-or-later
// The kept tree of a backward HeadingSearch: bounds, path validity after new obstacles, paths.
#include <algorithm>
#include <cmath>

#include "modules/planner/lib/heading_search.hpp"
#include "modules/planner/lib/lean_graph.hpp"

namespace robuter::plan {

void HeadingSearch::place_of(std::uint32_t s, int& x, int& y, int& slot) const {
  place_in(s & ((std::uint32_t{1} << page_shift_) - 1), origin_[s >> page_shift_], x, y, slot);
}

void HeadingSearch::walk_back(std::uint32_t s, std::vector<CellPose>& out) const {
  const int k_count = static_cast<int>(run_.in.slices.size());
  const int m_count = run_.m_count;
  const int s0 = run_.in.start.slice;
  for (;;) {
    int x, y, slot;
    place_of(s, x, y, slot);
    const int k = move_slice_[static_cast<std::size_t>(slot)];
    out.push_back({x - 1, y - 1, k});
    const int p = meta_[s] & kParentMask;
    if (p == kStartState) return;
    int from_slot = slot;
    int dir = 0;  // slice step walking back: -1 (it turned up), +1 (it turned down)
    int stop = -1;
    if (p < 8) {
      x -= kMoveDx[p];
      y -= kMoveDy[p];
    } else if (p == kTurnedUp || p == kSeedUp) {
      dir = -1;
      from_slot = (slot + m_count - 1) % m_count;
      stop = p == kSeedUp ? s0 : move_slice_[static_cast<std::size_t>(from_slot)];
    } else {
      dir = +1;
      from_slot = (slot + 1) % m_count;
      stop = p == kSeedDown ? s0 : move_slice_[static_cast<std::size_t>(from_slot)];
    }
    if (dir != 0) {
      for (int j = (k + dir + k_count) % k_count; j != stop; j = (j + dir + k_count) % k_count)
        out.push_back({x - 1, y - 1, j});
      if (p == kSeedUp || p == kSeedDown) {
        out.push_back({x - 1, y - 1, s0});
        return;
      }
    }
    s = state_at(x, y, from_slot);  // the parent: seen
  }
}

double HeadingSearch::tree_bound(int x, int y, int slot, std::uint32_t cell, std::uint32_t& settled) const {
  settled = kNoState;
  const double hf = toward_robot(x, y, cell, slot);
  if (const std::uint32_t s = state_at(x, y, slot); s != kNoState && (meta_[s] & kSettled)) {
    settled = s;
    return g_[s];
  }
  // Not settled: its cost to the goal plus the heuristic was at least the bound when the tree was
  // made (else the tree would hold it exactly), and costs have only risen since.
  if (hf == CostField::kInfinity || settle_ == CostField::kInfinity) return 0.0;
  return std::max(0.0, settle_ - hf);
}

bool HeadingSearch::settle_step(std::size_t max_states, PlanResult& out) {
  const PassGrid& g0 = *run_.in.slices[0];
  const auto stride = static_cast<std::uint32_t>(g0.stride);
  const std::size_t states = std::size_t{1} << page_shift_;
  const double below = settle_ + settle_slack(settle_);
  const std::size_t pages = std::max<std::size_t>(1, max_states / states);
  const std::size_t end = std::min(used_, run_.settle_page + pages);
  for (std::size_t page = run_.settle_page; page < end; ++page) {
    const PageOrigin& o = origin_[page];
    for (std::size_t i = 0; i < states; ++i) {
      const std::size_t s = (page << page_shift_) | i;
      if (!(meta_[s] & kSeen)) continue;
      int x, y, slot;
      place_in(static_cast<std::uint32_t>(i), o, x, y, slot);
      const std::uint32_t cell = static_cast<std::uint32_t>(y) * stride + static_cast<std::uint32_t>(x);
      if (bound_ == CostField::kInfinity || g_[s] + toward_robot(x, y, cell, slot) <= below)
        meta_[s] = static_cast<std::uint8_t>(meta_[s] | kSettled);
    }
  }
  run_.settle_page = end;
  if (end < used_) return false;
  run_.active = false;
  run_.settling = false;
  kept_ = true;
  out = run_.partial;
  if (bound_ == CostField::kInfinity) return true;
  for (std::uint32_t s = run_.reached;;) {  // the robot's tree path, to a seed at the goal
    meta_[s] = static_cast<std::uint8_t>(meta_[s] | kSettled);
    const int p = meta_[s] & kParentMask;
    if (p == kStartState) return true;
    int x, y, slot;
    place_of(s, x, y, slot);
    if (p < 8) {
      x -= kMoveDx[p];
      y -= kMoveDy[p];
    } else {
      slot = p == kTurnedUp ? (slot + run_.m_count - 1) % run_.m_count : (slot + 1) % run_.m_count;
    }
    s = state_at(x, y, slot);
  }
}

double HeadingSearch::toward_robot(int x, int y, std::uint32_t cell) const {
  const double d = octile(x - (run_.in.goal.x + 1), y - (run_.in.goal.y + 1));
  if (run_.in.heuristic == nullptr) return d;
  const double to_goal = run_.in.heuristic->cost_at(cell);
  if (to_goal == CostField::kInfinity) return CostField::kInfinity;  // on no path to the goal
  return std::max(d, robot_h_ - to_goal);
}

void HeadingSearch::new_epoch() {
  if (++epoch_ >= 0x80) {  // the memo's tags wrap: clear the pages in use
    std::fill_n(memo_.get(), used_ << page_shift_, std::uint8_t{0});
    epoch_ = 1;
  }
}

HeadingSearch::TreeEdges HeadingSearch::tree_edges() const {
  const PassGrid& g0 = *run_.in.slices[0];
  const LeanGraph lg = graph(run_.in.slices, goal_cell_, 0, goal_cell_);
  return TreeEdges{static_cast<int>(run_.in.slices.size()), run_.m_count, static_cast<std::uint32_t>(g0.stride),
                   MoveTable(g0.stride), run_.in.costs.table(), std::max(run_.in.options.rotation_step_cost, 0.0),
                   lg, lg.turn_bits != nullptr};
}

bool HeadingSearch::tree_valid(std::uint32_t state) {
  const auto tag = static_cast<std::uint8_t>(epoch_ << 1);
  const TreeEdges e = tree_edges();
  const auto& [k_count, m_count, stride, mt, cost, turn, lg, grown] = e;
  chain_.clear();
  bool ok = true;
  for (std::uint32_t s = state;;) {
    const std::uint8_t m = memo_[s];
    if ((m & 0xFFFEu) == tag) {
      ok = (m & 1u) != 0;
      break;
    }
    chain_.push_back(s);
    if (chain_.size() > budget_) {  // cannot happen (parents form a tree); never loop
      ok = false;
      break;
    }
    int x, y, slot;
    place_of(s, x, y, slot);
    const int k = move_slice_[static_cast<std::size_t>(slot)];
    const std::uint8_t* cls = cls_of_[static_cast<std::size_t>(k)];
    const std::uint32_t u = static_cast<std::uint32_t>(y) * stride + static_cast<std::uint32_t>(x);
    const int p = meta_[s] & kParentMask;
    if (cls[u] == kBlocked) {
      ok = false;
      break;
    }
    if (p == kStartState) break;  // a seed at the goal, still free: ok
    int qx = x, qy = y, q_slot = slot;
    double c = 0.0;
    if (p < 8) {  // reached from q by move p: the robot moves back from u to q
      qx -= kMoveDx[p];
      qy -= kMoveDy[p];
      const std::uint32_t q = u - static_cast<std::uint32_t>(mt.step[p]);
      if (cls[q] == kBlocked || !mt.passable(cls, q, p)) {
        ok = false;
        break;
      }
      c = cost[p][cls[q]][cls[u]];
    } else {  // reached by a turn from the next slot down (up) the ring: the robot turns back
      const bool up = p == kTurnedUp;
      q_slot = up ? (slot + m_count - 1) % m_count : (slot + 1) % m_count;
      const int qk = move_slice_[static_cast<std::size_t>(q_slot)];
      const int n = up ? (k - qk + k_count) % k_count : (qk - k + k_count) % k_count;
      if (!arc_free(lg, grown, u, k, n, up ? -1 : +1)) {
        ok = false;
        break;
      }
      c = n * turn;
    }
    const std::uint32_t qs = state_at(qx, qy, q_slot);  // the parent: seen
    if (qs == kNoState || g_[qs] + c != g_[s]) {  // the edge's cost changed (a cell's class did)
      ok = false;
      break;
    }
    s = qs;
  }
  const auto val = static_cast<std::uint8_t>(tag | (ok ? 1u : 0u));
  for (const std::uint32_t c : chain_) memo_[c] = val;
  return ok;
}

std::uint32_t HeadingSearch::state_at(int x, int y, int slot) const {
  const TileEntry& te = tiles_[entry_of(x, y, slot)];
  if (te.stamp != gen_) return kNoState;
  const std::uint32_t s = state_in(te.page, x, y, slot);
  return (meta_[s] & kSeen) ? s : kNoState;
}

// From a valid settled state to the goal, each step to a neighbour whose exact value is the
// state's less the edge (so the path is optimal), preferring the move just made, then any move,
// then a turn: among paths of equal cost the robot keeps going straight and turns late, as a
// search from the robot would, rather than in the order the tree happened to settle them. The
// tree's own parent is always such a neighbour, so the descent never fails.
void HeadingSearch::append_tree_path(std::uint32_t state, int last_move, std::vector<CellPose>& out) {
  const TreeEdges e = tree_edges();
  const auto& [k_count, m_count, stride, mt, cost, turn, lg, grown] = e;
  auto settled_valid = [&](int x, int y, int slot) {
    const std::uint32_t q = state_at(x, y, slot);
    if (q == kNoState) return kNoState;
    return (meta_[q] & kSettled) && tree_valid(q) ? q : kNoState;
  };
  std::uint32_t s = state;
  for (std::size_t steps = 0; steps < budget_; ++steps) {
    int x, y, slot;
    place_of(s, x, y, slot);
    const std::uint32_t u = static_cast<std::uint32_t>(y) * stride + static_cast<std::uint32_t>(x);
    if (u == goal_cell_) return;
    const int k = move_slice_[static_cast<std::size_t>(slot)];
    const std::uint8_t* cls = cls_of_[static_cast<std::size_t>(k)];
    const double gs = g_[s];
    auto on_optimal = [&](std::uint32_t q, double c) {
      return q != kNoState && c > 0.0 && std::abs(c + g_[q] - gs) <= 1e-9 * std::max(1.0, gs);
    };
    // Candidates in order of preference: a move to a cell with the turn clearance round the body
    // (the last move first), any move (the last first), the turns.
    auto roomy = [&](std::uint32_t v) {
      return !grown || ((lg.turn_bits[v * static_cast<std::uint32_t>(lg.turn_words) + static_cast<std::uint32_t>(k >> 5)] >>
                         (k & 31)) & 1u) == 0;
    };
    std::uint32_t next = kNoState;
    int next_move = -1, n_turn = 0, turn_dir = 0;
    for (int pass = 0; pass < 4 && next == kNoState; ++pass)
      for (int m = 0; m < 8 && next == kNoState; ++m) {
        if ((pass % 2 == 0) != (m == last_move) || !(allowed_[static_cast<std::size_t>(k)] & (1u << m))) continue;
        const std::uint32_t v = u + static_cast<std::uint32_t>(mt.step[m]);
        if (!mt.passable(cls, u, m) || (pass < 2 && !roomy(v))) continue;
        const std::uint32_t q = settled_valid(x + kMoveDx[m], y + kMoveDy[m], slot);
        if (on_optimal(q, cost[m][cls[u]][cls[v]])) {
          next = q;
          next_move = m;
        }
      }
    for (int dir = 1; dir >= -1 && next == kNoState && m_count > 1; dir -= 2) {
      const int to = dir > 0 ? (slot + 1) % m_count : (slot + m_count - 1) % m_count;
      const int tk = move_slice_[static_cast<std::size_t>(to)];
      const int n = dir > 0 ? (tk - k + k_count) % k_count : (k - tk + k_count) % k_count;
      if (!arc_free(lg, grown, u, k, n, dir)) continue;
      const std::uint32_t q = settled_valid(x, y, to);
      if (on_optimal(q, n * turn)) {
        next = q;
        n_turn = n;
        turn_dir = dir;
      }
    }
    if (next == kNoState) {  // only zero-cost turns left (no turn cost): the tree's own path
      const std::size_t first = out.size();
      walk_back(s, out);
      out.erase(out.begin() + static_cast<std::ptrdiff_t>(first));
      return;
    }
    if (next_move >= 0) {
      out.push_back({x + kMoveDx[next_move] - 1, y + kMoveDy[next_move] - 1, k});
    } else {
      for (int q = 1; q <= n_turn; ++q) out.push_back({x - 1, y - 1, ((k + turn_dir * q) % k_count + k_count) % k_count});
    }
    last_move = next_move;
    s = next;
  }
}

}  // namespace robuter::plan
