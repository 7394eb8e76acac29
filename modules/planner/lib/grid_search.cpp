// SPDX-License-Identifier: GPL-3.0-or-later
// A* (bucket open list, heap fallback) and the thesis' breadth-first search, on preallocated arrays.
#include "modules/planner/lib/grid_search.hpp"

#include <algorithm>
#include <bit>
#include <limits>

namespace robuter::plan {

void GridSearch::reserve(int width, int height) {
  const auto stored = static_cast<std::size_t>(width + 2) * static_cast<std::size_t>(height + 2);
  if (mark_.size() < stored) {
    mark_.assign(stored, 0);
    g_.resize(stored);
    parent_.resize(stored);
    next_.resize(stored);
    prev_.resize(stored);
    queue_.resize(stored);
    from_.resize(stored);
    gen_ = 0;
  }
  open_.reserve(stored);
  head_.reserve(4096);
  samples_.reserve(kSamples);
  path_.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) + 1);
}

// Why: a new generation invalidates every mark at once; on wrap-around the marks are reset.
void GridSearch::next_generation() {
  if (++gen_ >= (1u << 31)) {
    std::fill(mark_.begin(), mark_.end(), 0u);
    gen_ = 1;
  }
}

PlanResult GridSearch::find(const PassGrid& grid, Cell start, Cell goal, SearchMode mode,
                            const CostModel& costs) {
  PlanResult r;
  path_.clear();
  if (!grid.contains(start)) return r.status = PlanStatus::StartOutside, r;
  if (!grid.contains(goal)) return r.status = PlanStatus::GoalOutside, r;
  if (grid.at(start) == kBlocked) return r.status = PlanStatus::StartBlocked, r;
  if (grid.at(goal) == kBlocked) return r.status = PlanStatus::GoalBlocked, r;
  reserve(grid.width, grid.height);
  next_generation();
  const std::uint32_t s = grid.index(start);
  const std::uint32_t t = grid.index(goal);
  if (mode == SearchMode::Bfs) return bfs(grid, s, t, costs);
  const bool uniform = costs.unknown_cost <= 1.0;
  const double widest = 2.0 * kSqrt2 * std::max(1.0, costs.unknown_cost);
  const bool ring_ok = widest / kBucketWidth + 4.0 <= 4096.0;
  switch (engine_) {
    case Engine::JumpPoints:
      if (uniform) return astar_jps(grid, s, t, costs);
      break;
    case Engine::Buckets:
      if (ring_ok) return astar_buckets(grid, s, t, costs);
      break;
    case Engine::Heap:
      return astar(grid, s, t, costs);
    case Engine::Auto:
      if (uniform && prefers_jump_points(grid)) return astar_jps(grid, s, t, costs);
      break;
  }
  if (ring_ok) return astar_buckets(grid, s, t, costs);
  return astar(grid, s, t, costs);
}

// Why: the sample positions depend only on the grid size: computed once per size.
void GridSearch::sample_cells(const PassGrid& grid) {
  if (sample_width_ == grid.width && sample_height_ == grid.height) return;
  sample_width_ = grid.width;
  sample_height_ = grid.height;
  const auto cells = static_cast<std::uint64_t>(grid.width) * static_cast<std::uint64_t>(grid.height);
  const std::uint64_t n = std::min<std::uint64_t>(cells, kSamples);
  samples_.clear();
  for (std::uint64_t k = 0; k < n; ++k) {
    // Evenly spread, deterministic positions (golden-ratio stride through the cells).
    const std::uint64_t c = n == cells ? k : (k * 0x9E3779B97F4A7C15ull >> 11) % cells;
    samples_.push_back(grid.index({static_cast<int>(c % static_cast<std::uint64_t>(grid.width)),
                                   static_cast<int>(c / static_cast<std::uint64_t>(grid.width))}));
  }
}

double GridSearch::scattered_fraction(const PassGrid& grid) {
  sample_cells(grid);
  const std::uint8_t* cls = grid.cls.data();
  const auto sn = static_cast<std::uint32_t>(grid.stride);
  int blocked = 0;
  int scattered = 0;
  for (const std::uint32_t i : samples_) {
    if (cls[i] != kBlocked) continue;
    ++blocked;
    const int walls = (cls[i + 1] == kBlocked) + (cls[i - 1] == kBlocked) +
                      (cls[i + sn] == kBlocked) + (cls[i - sn] == kBlocked);
    scattered += walls <= 1 ? 1 : 0;
  }
  // No obstacle in the sample: nothing to jump over; the bucket A* crosses open space faster.
  return blocked == 0 ? 1.0 : static_cast<double>(scattered) / blocked;
}

double GridSearch::run_fraction(const PassGrid& grid) {
  sample_cells(grid);
  const std::uint8_t* cls = grid.cls.data();
  const auto sn = static_cast<std::uint32_t>(grid.stride);
  int open = 0;
  int runs = 0;
  for (const std::uint32_t i : samples_) {
    if (cls[i] == kBlocked) continue;
    ++open;
    const bool e = cls[i + 1] == kBlocked, w = cls[i - 1] == kBlocked;
    const bool n = cls[i + sn] == kBlocked, s = cls[i - sn] == kBlocked;
    const bool all_free = !e && !w && !n && !s && cls[i + sn + 1] != kBlocked && cls[i + sn - 1] != kBlocked &&
                          cls[i - sn + 1] != kBlocked && cls[i - sn - 1] != kBlocked;
    runs += all_free || (e && w) || (n && s) ? 1 : 0;
  }
  return open == 0 ? 0.0 : static_cast<double>(runs) / open;
}

// Why: the fallback for very uneven costs. Octile h is consistent, so a node is final when
// popped; ties on f go to the smaller h (deeper node).
PlanResult GridSearch::astar(const PassGrid& grid, std::uint32_t s, std::uint32_t t,
                             const CostModel& costs) {
  const MoveTable mt(grid.stride);
  const auto cost = costs.table();
  const std::uint8_t* cls = grid.cls.data();
  std::uint32_t* mark = mark_.data();
  double* g = g_.data();
  std::uint8_t* parent = parent_.data();
  const std::uint32_t seen = gen_ << 1, closed = seen | 1u;
  const auto stride = static_cast<std::uint32_t>(grid.stride);
  const int tx = static_cast<int>(t % stride);
  const int ty = static_cast<int>(t / stride);
  PlanResult r;

  open_.clear();
  mark[s] = seen;
  g[s] = 0.0;
  parent[s] = kNoMove;
  {
    const double h = octile(static_cast<int>(s % stride) - tx, static_cast<int>(s / stride) - ty);
    open_.push(s, h, static_cast<float>(h));
  }
  while (!open_.empty()) {
    const std::uint32_t u = open_.pop().node;
    mark[u] = closed;
    ++r.expanded;
    if (u == t) {
      r.status = PlanStatus::Found;
      build_path(grid, mt, s, t, r, costs);
      return r;
    }
    const int ux = static_cast<int>(u % stride);
    const int uy = static_cast<int>(u / stride);
    const double gu = g[u];
    const std::uint8_t cu = cls[u];
    for (int m = 0; m < 8; ++m) {
      const std::uint32_t v = u + static_cast<std::uint32_t>(mt.step[m]);
      const std::uint8_t cv = cls[v];
      if (cv == kBlocked) continue;
      if (m >= 4 && (cls[u + static_cast<std::uint32_t>(mt.side_a[m])] == kBlocked ||
                     cls[u + static_cast<std::uint32_t>(mt.side_b[m])] == kBlocked))
        continue;
      const double ng = gu + cost[m][cu][cv];
      if (mark[v] != seen && mark[v] != closed) {
        mark[v] = seen;
        g[v] = ng;
        parent[v] = static_cast<std::uint8_t>(m);
        const double h = octile(ux + kMoveDx[m] - tx, uy + kMoveDy[m] - ty);
        open_.push(v, ng + h, static_cast<float>(h));
      } else if (mark[v] == seen && ng < g[v]) {
        g[v] = ng;
        parent[v] = static_cast<std::uint8_t>(m);
        const double h = octile(ux + kMoveDx[m] - tx, uy + kMoveDy[m] - ty);
        open_.decrease(v, ng + h, static_cast<float>(h));
      }
    }
  }
  return r;  // Unreachable
}

// Why: the default optimal search (see the header): O(1) open-list operations.
PlanResult GridSearch::astar_buckets(const PassGrid& grid, std::uint32_t s, std::uint32_t t,
                                     const CostModel& costs) {
  const MoveTable mt(grid.stride);
  const auto cost = costs.table();
  const std::uint8_t* cls = grid.cls.data();
  std::uint32_t* mark = mark_.data();
  double* g = g_.data();
  std::uint8_t* parent = parent_.data();
  std::uint32_t* next = next_.data();
  std::uint32_t* prev = prev_.data();
  const std::uint32_t seen = gen_ << 1, closed = seen | 1u;
  const bool uniform = costs.unknown_cost <= 1.0;
  const auto stride = static_cast<std::uint32_t>(grid.stride);
  const int tx = static_cast<int>(t % stride);
  const int ty = static_cast<int>(t / stride);
  // Ring size: open nodes span at most 2 * (largest edge cost) of f above the lowest one.
  const double widest = 2.0 * kSqrt2 * std::max(1.0, costs.unknown_cost);
  std::uint32_t ring = 8;
  while (ring < static_cast<std::uint32_t>(widest / kBucketWidth) + 4) ring <<= 1;
  const std::uint64_t mask = ring - 1;
  head_.assign(ring, kNil);
  std::uint32_t* head = head_.data();
  constexpr double inv_width = 1.0 / kBucketWidth;
  auto bucket_of = [&](double f) { return static_cast<std::uint64_t>(f * inv_width); };
  auto link = [&](std::uint32_t v, std::uint64_t b) {
    const auto slot = static_cast<std::uint32_t>(b & mask);
    const std::uint32_t first = head[slot];
    next[v] = first;
    prev[v] = kNil;
    if (first != kNil) prev[first] = v;
    head[slot] = v;
  };
  auto unlink = [&](std::uint32_t v, std::uint64_t b) {
    const std::uint32_t p = prev[v], n = next[v];
    if (p != kNil) next[p] = n;
    else head[static_cast<std::uint32_t>(b & mask)] = n;
    if (n != kNil) prev[n] = p;
  };

  PlanResult r;
  double best = std::numeric_limits<double>::infinity();
  const double hs = octile(static_cast<int>(s % stride) - tx, static_cast<int>(s / stride) - ty);
  mark[s] = seen;
  g[s] = 0.0;
  parent[s] = kNoMove;
  std::uint64_t cur = bucket_of(hs);
  link(s, cur);
  std::size_t open = 1;
  if (s == t) best = 0.0;
  // A key below bucket `cur` (octile h is consistent, so only rounding can do it) is filed in
  // `cur`, and `below` keeps the lowest such key: the stop test must not pass it.
  constexpr double kNone = 1e300;
  double below = kNone;
  const std::uint32_t sn = stride;
  while (open > 0) {
    while (head[cur & mask] == kNil) ++cur, below = kNone;
    if (std::min(static_cast<double>(cur) * kBucketWidth, below) >= best) break;
    const std::uint32_t u = head[cur & mask];
    unlink(u, cur);
    --open;
    mark[u] = closed;
    const std::uint32_t row = u / stride;
    const int ux = static_cast<int>(u - row * stride);
    const int uy = static_cast<int>(row);
    const double gu = g[u];
    if (u == t || gu + octile(ux - tx, uy - ty) >= best) continue;
    ++r.expanded;
    const std::uint8_t cu = cls[u];
    // Legal moves as a bit mask, computed without branches: orthogonal moves need the cell,
    // diagonal moves the cell and both side cells (move m's side cells are orthogonal moves).
    const std::uint32_t n0 = cls[u + sn] != kBlocked, n1 = cls[u + 1] != kBlocked;
    const std::uint32_t n2 = cls[u - sn] != kBlocked, n3 = cls[u - 1] != kBlocked;
    const std::uint32_t d4 = cls[u + sn + 1] != kBlocked, d5 = cls[u - sn + 1] != kBlocked;
    const std::uint32_t d6 = cls[u - sn - 1] != kBlocked, d7 = cls[u + sn - 1] != kBlocked;
    std::uint32_t legal = n0 | n1 << 1 | n2 << 2 | n3 << 3 | (d4 & n1 & n0) << 4 |
                          (d5 & n1 & n2) << 5 | (d6 & n3 & n2) << 6 | (d7 & n3 & n0) << 7;
    while (legal) {
      const int m = std::countr_zero(legal);
      legal &= legal - 1;
      const std::uint32_t v = u + static_cast<std::uint32_t>(mt.step[m]);
      const double ng = uniform ? gu + (m < 4 ? 1.0 : kSqrt2) : gu + cost[m][cu][cls[v]];
      const std::uint32_t mv = mark[v];
      const bool known = (mv | 1u) == closed;
      if (known && !(ng < g[v] - 1e-9)) continue;
      const double hv = octile(ux + kMoveDx[m] - tx, uy + kMoveDy[m] - ty);
      if (!known) {
        ++open;
      } else if (mv == closed) {
        ++open;  // reopened: its first expansion came a little early
      } else {
        unlink(v, std::max(bucket_of(g[v] + hv), cur));  // where link() filed it
      }
      mark[v] = seen;
      g[v] = ng;
      parent[v] = static_cast<std::uint8_t>(m);
      const double fv = ng + hv;
      std::uint64_t bv = bucket_of(fv);
      if (bv < cur) bv = cur, below = std::min(below, fv);
      link(v, bv);
      if (v == t) best = std::min(best, ng);
    }
  }
  if (best == std::numeric_limits<double>::infinity()) return r;  // Unreachable
  r.status = PlanStatus::Found;
  build_path(grid, mt, s, t, r, costs);
  return r;
}

// Why: the thesis' algorithm (gera_trajetoria) kept as a mode, with its neighbour order and
// the corner-cutting rule fixed: fewest moves, not shortest length.
PlanResult GridSearch::bfs(const PassGrid& grid, std::uint32_t s, std::uint32_t t,
                           const CostModel& costs) {
  const MoveTable mt(grid.stride);
  const std::uint8_t* cls = grid.cls.data();
  std::uint32_t* mark = mark_.data();
  std::uint8_t* parent = parent_.data();
  std::uint32_t* queue = queue_.data();
  const std::uint32_t seen = gen_ << 1;
  PlanResult r;
  std::size_t head = 0;
  std::size_t tail = 0;
  mark[s] = seen;
  parent[s] = kNoMove;
  queue[tail++] = s;
  while (head < tail) {
    const std::uint32_t u = queue[head++];
    ++r.expanded;
    if (u == t) {
      r.status = PlanStatus::Found;
      build_path(grid, mt, s, t, r, costs);
      return r;
    }
    for (int m = 0; m < 8; ++m) {
      const std::uint32_t v = u + static_cast<std::uint32_t>(mt.step[m]);
      if (cls[v] == kBlocked || mark[v] == seen) continue;
      if (m >= 4 && (cls[u + static_cast<std::uint32_t>(mt.side_a[m])] == kBlocked ||
                     cls[u + static_cast<std::uint32_t>(mt.side_b[m])] == kBlocked))
        continue;
      mark[v] = seen;
      parent[v] = static_cast<std::uint8_t>(m);
      queue[tail++] = v;
    }
  }
  return r;  // Unreachable
}

// Why: walk the parent moves back from the goal, then reverse; cost and length are summed
// from the moves so every mode reports them the same way.
void GridSearch::build_path(const PassGrid& grid, const MoveTable& mt, std::uint32_t s,
                            std::uint32_t t, PlanResult& r, const CostModel& costs) {
  const auto cost = costs.table();
  std::uint32_t v = t;
  int orth = 0;
  int diag = 0;
  double c = 0.0;
  path_.clear();
  path_.push_back(grid.cell(v));
  while (v != s) {
    const int m = parent_[v];
    const std::uint32_t u = v - static_cast<std::uint32_t>(mt.step[m]);
    (m < 4 ? orth : diag) += 1;
    c += cost[m][grid.cls[u]][grid.cls[v]];
    v = u;
    path_.push_back(grid.cell(v));
  }
  std::reverse(path_.begin(), path_.end());
  r.length = static_cast<double>(orth) + kSqrt2 * static_cast<double>(diag);
  r.cost = c;
}

}  // namespace robuter::plan
