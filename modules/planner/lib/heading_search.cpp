// SPDX-License-Identifier: GPL-3.0-or-later
// A* over (cell, heading slice) with in-place turns and a relaxation field as heuristic.
#include "modules/planner/lib/heading_search.hpp"

#include <algorithm>
#include <cmath>

#include "modules/planner/lib/footprint.hpp"

namespace robuter::plan {

std::uint8_t allowed_moves(int slice, int slices, MotionModel motion) {
  if (motion == MotionModel::Holonomic) return 0xFF;
  const double half = kPi / slices + 1e-9;  // half of a full-turn slice
  const double th = slice_heading(slice, slices);
  std::uint8_t bits = 0;
  for (int m = 0; m < 8; ++m) {
    const double dir = std::atan2(static_cast<double>(kMoveDy[m]), static_cast<double>(kMoveDx[m]));
    double d = wrap_angle(dir - th, kPi);
    d = std::min(d, kPi - d);
    if (d <= half) bits = static_cast<std::uint8_t>(bits | (1u << m));
  }
  return bits;
}

namespace {

// meta_ bits of a pool state.
constexpr std::uint8_t kParentMask = 0x0F;  // how the state was reached (below)
constexpr std::uint8_t kSeen = 0x10;        // reached in this search (g_ is valid)
constexpr std::uint8_t kClosed = 0x20;      // expanded
// Parent codes (0..7: the grid move that led here).
constexpr std::uint8_t kTurnedUp = 8;     // turned up from the move slot below
constexpr std::uint8_t kTurnedDown = 9;   // turned down from the move slot above
constexpr std::uint8_t kSeedUp = 10;      // turned up from a pass-through start slice
constexpr std::uint8_t kSeedDown = 11;    // turned down from a pass-through start slice
constexpr std::uint8_t kStartState = 15;  // the start itself

// Why: the search's heuristic at a stored cell (x, y) of index `cell`: the relaxation field when
// there is one, else the octile distance to the goal (grid cell `goal`, stored at goal + 1).
double heuristic_at(const CostField* field, Cell goal, int x, int y, std::uint32_t cell) {
  if (field) return field->cost_at(cell);
  return octile(x - (goal.x + 1), y - (goal.y + 1));
}

// Why: pages hold a power of two of move slots, so a state's slot is a shift away.
int log2_ceil(std::size_t n) {
  int b = 0;
  while ((std::size_t{1} << b) < n) ++b;
  return b;
}

}  // namespace

void HeadingSearch::reserve(int width, int height, int slices, std::size_t state_budget) {
  const int k = std::max(slices, 1);
  const int sw = width + 2;
  const int sh = height + 2;
  tiles_x_ = (sw + (1 << kTileShift) - 1) >> kTileShift;
  const int tiles_y = (sh + (1 << kTileShift) - 1) >> kTileShift;
  const auto tiles = static_cast<std::size_t>(tiles_x_) * static_cast<std::size_t>(tiles_y);
  if (tiles_.size() < tiles) {
    tiles_.assign(tiles, TileEntry{});
    gen_ = 0;
  }
  // At least one page of the largest kind (every slice a move slice).
  const std::size_t one_page = std::size_t{1} << (2 * kTileShift + log2_ceil(static_cast<std::size_t>(k)));
  const std::size_t budget = std::max(state_budget, one_page);
  if (budget_ < budget) {
    g_.reset(new double[budget]);  // uninitialised: resident only where a search writes
    meta_.reset(new std::uint8_t[budget]);
    resident_pages_ = 0;  // fresh memory
  }
  budget_ = budget;
  if (origin_.size() < budget / kTileCells) origin_.resize(budget / kTileCells);
  open_.reserve(budget);
  ring_.reserve(budget);
  const auto stored = static_cast<std::size_t>(sw) * static_cast<std::size_t>(sh);
  path_.reserve(2 * stored + static_cast<std::size_t>(k));
  const auto kk = static_cast<std::size_t>(k);
  if (cls_of_.size() < kk) cls_of_.resize(kk, nullptr);
  if (allowed_.size() < kk) allowed_.resize(kk, 0);
  if (move_slice_.size() < kk) move_slice_.resize(kk, 0);
  if (slot_of_.size() < kk) slot_of_.resize(kk, -1);
  enclosure_.reserve(k);
}

PlanResult HeadingSearch::find(std::span<const PassGrid* const> slices, CellPose start, Cell goal,
                               const HeadingOptions& options, const CostModel& costs,
                               const CostField* heuristic, const SliceBits* turn_room) {
  PlanResult r;
  if (begin(slices, start, goal, options, costs, heuristic, turn_room, r)) return r;
  resume(~std::uint32_t{0}, r);
  return r;
}

bool HeadingSearch::begin(std::span<const PassGrid* const> slices, CellPose start, Cell goal,
                          const HeadingOptions& options, const CostModel& costs,
                          const CostField* heuristic, const SliceBits* turn_room, PlanResult& out) {
  PlanResult r;
  path_.clear();
  used_ = 0;
  run_.active = false;
  shut_in_ = false;
  const auto done = [&](PlanStatus st) {
    r.status = st;
    out = r;
    return true;
  };
  const int k_count = static_cast<int>(slices.size());
  if (k_count == 0) return done(PlanStatus::Unreachable);
  const PassGrid& g0 = *slices[0];
  const Cell sc{start.x, start.y};
  if (!g0.contains(sc)) return done(PlanStatus::StartOutside);
  if (!g0.contains(goal)) return done(PlanStatus::GoalOutside);
  start.slice = ((start.slice % k_count) + k_count) % k_count;
  if (slices[static_cast<std::size_t>(start.slice)]->at(sc) == kBlocked) return done(PlanStatus::StartBlocked);
  bool goal_free = false;
  for (const PassGrid* g : slices) goal_free = goal_free || g->at(goal) != kBlocked;
  if (!goal_free) return done(PlanStatus::GoalBlocked);

  reserve(g0.width, g0.height, k_count, budget_ == 0 ? kDefaultStateBudget : budget_);
  if (++gen_ == 0) {
    for (TileEntry& e : tiles_) e.stamp = 0;
    gen_ = 1;
  }
  std::uint8_t* allowed = allowed_.data();
  const std::uint8_t** cls_of = cls_of_.data();
  int* move_slice = move_slice_.data();
  int* slot_of = slot_of_.data();
  int m_count = 0;  // move slots
  for (int k = 0; k < k_count; ++k) {
    allowed[k] = allowed_moves(k, k_count, options.motion);
    cls_of[k] = slices[static_cast<std::size_t>(k)]->cls.data();
    slot_of[k] = -1;
    if (allowed[k] != 0) {
      slot_of[k] = m_count;
      move_slice[m_count++] = k;
    }
  }
  page_shift_ = 2 * kTileShift + log2_ceil(static_cast<std::size_t>(std::max(m_count, 1)));
  pages_ = budget_ >> page_shift_;
  const std::uint32_t t = g0.index(goal);
  const double turn = std::max(options.rotation_step_cost, 0.0);

  // Open list: the bucket ring when edge costs are bounded enough, else the heap (see
  // BucketRing: with the ring, closed states may be reopened and the loop ends when the lowest
  // bucket reaches the best goal cost; with the heap, when the popped f reaches it). A turn
  // edge spans up to k_count - 1 slice steps.
  const double max_edge =
      std::max(kSqrt2 * std::max(1.0, costs.unknown_cost), turn * std::max(k_count - 1, 1));
  const int sx = sc.x + 1;
  const int sy = sc.y + 1;
  const std::uint32_t start_index = g0.index(sc);
  const double h0 = heuristic_at(heuristic, goal, sx, sy, start_index);
  if (h0 == CostField::kInfinity) return done(PlanStatus::Unreachable);  // the relaxation says so
  if (start_index == t) {  // already there, at the start heading
    path_.push_back(start);
    return done(PlanStatus::Found);
  }
  if (m_count == 0) return done(PlanStatus::Unreachable);  // no slice allows a grid move
  const bool use_ring = !options.heap && ring_.reset(kBucketWidth, max_edge, h0);
  open_.clear();
  run_ = Run{};
  run_.slices = slices;
  run_.start = start;
  run_.goal = goal;
  run_.options = options;
  run_.costs = costs;
  run_.heuristic = heuristic;
  run_.turn_room = turn_room;
  run_.m_count = m_count;
  run_.use_ring = use_ring;
  run_.active = true;
  return false;
}

bool HeadingSearch::resume(std::uint32_t max_pops, PlanResult& out) {
  if (!run_.active) return true;
  // The search's inputs, and what begin() derived from them, as locals: the loop below reads
  // them from registers, not through `this` (its writes to meta_ may alias any member).
  const std::span<const PassGrid* const> slices = run_.slices;
  const CellPose start = run_.start;
  const Cell goal = run_.goal;
  const HeadingOptions& options = run_.options;
  const CostModel& costs = run_.costs;
  const CostField* const heuristic = run_.heuristic;
  const SliceBits* const turn_room = run_.turn_room;
  const int k_count = static_cast<int>(slices.size());
  const int m_count = run_.m_count;
  const bool use_ring = run_.use_ring;
  const PassGrid& g0 = *slices[0];
  const Cell sc{start.x, start.y};
  const auto stride = static_cast<std::uint32_t>(g0.stride);
  const MoveTable mt(g0.stride);
  const auto cost = costs.table();
  std::uint8_t* allowed = allowed_.data();
  const std::uint8_t** cls_of = cls_of_.data();
  int* move_slice = move_slice_.data();
  int* slot_of = slot_of_.data();
  const bool own_turns = turn_room != nullptr && turn_room->slices == k_count;
  const int shift = page_shift_;
  const std::uint32_t local_mask = (std::uint32_t{1} << shift) - 1;
  const std::uint32_t t = g0.index(goal);
  auto h_of = [&](int x, int y, std::uint32_t cell) { return heuristic_at(heuristic, goal, x, y, cell); };
  const double turn = std::max(options.rotation_step_cost, 0.0);
  double* g = g_.get();
  std::uint8_t* meta = meta_.get();
  TileEntry* tiles = tiles_.data();
  PageOrigin* origin = origin_.data();
  const int tiles_x = tiles_x_;
  constexpr int tmask = (1 << kTileShift) - 1;
  auto tile_of = [&](int x, int y) -> TileEntry& {
    return tiles[(y >> kTileShift) * tiles_x + (x >> kTileShift)];
  };
  auto id_in = [&](std::uint32_t page, int x, int y, int slot) -> std::uint32_t {
    return (page << shift) | (static_cast<std::uint32_t>(slot) << (2 * kTileShift)) |
           (static_cast<std::uint32_t>(y & tmask) << kTileShift) | static_cast<std::uint32_t>(x & tmask);
  };
  const int sx = sc.x + 1;
  const int sy = sc.y + 1;
  const std::uint32_t start_index = g0.index(sc);
  PlanResult r = run_.partial;
  // A page no search has written yet costs its first touch (the kernel maps its memory: ~25 µs
  // here, as much as ~250 pops), charged to the step's budget so that a first search through
  // fresh memory takes more steps, not a longer one. Pages are handed out in order, so those
  // below the high-water mark are resident.
  const std::size_t resident = resident_pages_;
  std::uint32_t charged = 0;
  double best = run_.best;
  std::uint32_t reached = run_.reached;
  bool limit = run_.limit;

  auto relax = [&](int x, int y, int slot, double ng, std::uint8_t how) {
    const std::uint32_t cell = static_cast<std::uint32_t>(y) * stride + static_cast<std::uint32_t>(x);
    TileEntry& te = tile_of(x, y);
    double h = -1.0;
    if (te.stamp != gen_) {
      h = h_of(x, y, cell);
      if (h == CostField::kInfinity) return;  // the relaxation cannot reach the goal from here
      if (used_ == pages_) {
        limit = true;  // the pool is spent: the search cannot finish exactly
        return;
      }
      te.stamp = gen_;
      if (used_ >= resident) charged += kFirstTouchPops;
      te.page = static_cast<std::uint32_t>(used_++);
      origin[te.page] = PageOrigin{x & ~tmask, y & ~tmask};
      std::fill_n(meta + (static_cast<std::size_t>(te.page) << shift), std::size_t{1} << shift,
                  std::uint8_t{0});
    }
    const std::uint32_t s = id_in(te.page, x, y, slot);
    std::uint8_t& mt_s = meta[s];
    if (!(mt_s & kSeen)) {
      if (h < 0.0) h = h_of(x, y, cell);
      if (h == CostField::kInfinity) return;
      g[s] = ng;
      mt_s = static_cast<std::uint8_t>(kSeen | how);
      if (use_ring) ring_.push(s, ng + h);
      else open_.push(s, ng + h, static_cast<float>(h));
    } else if (ng < g[s] - 1e-9 && (use_ring || !(mt_s & kClosed))) {
      h = h_of(x, y, cell);
      if (mt_s & kClosed) {
        ring_.push(s, ng + h);  // reopened (ring only): its first expansion came a little early
      } else if (use_ring) {
        ring_.lower_key(s, g[s] + h, ng + h);
      } else {
        open_.decrease(s, ng + h, static_cast<float>(h));
      }
      g[s] = ng;
      mt_s = static_cast<std::uint8_t>(kSeen | how);
    } else {
      return;
    }
    if (cell == t && ng < best) {
      best = ng;
      reached = s;
    }
  };

  const int s0 = start.slice;
  const LeanGraph lg{cls_of, k_count, g0.stride, g0.height + 2, move_slice, m_count, slot_of, allowed,
                     own_turns ? turn_room->bits.data() : nullptr, own_turns ? turn_room->words : 1,
                     start_index, s0, t};
  if (!run_.seeded) {
    run_.seeded = true;
    if (slot_of[s0] >= 0) {
      relax(sx, sy, slot_of[s0], 0.0, kStartState);
    } else {
      // A pass-through start slice: seed the nearest move slices either way (at the start cell
      // the body's own room is enough to turn).
      int n_up = 0, n_down = 0;
      const int up = next_move_slice(lg, s0, +1, n_up);
      const int down = next_move_slice(lg, s0, -1, n_down);
      if (arc_free(lg, false, start_index, s0, n_up, +1))
        relax(sx, sy, slot_of[up], n_up * turn, kSeedUp);
      if (arc_free(lg, false, start_index, s0, n_down, -1))
        relax(sx, sy, slot_of[down], n_down * turn, kSeedDown);
    }
  }
  for (std::uint32_t pops = 0; !limit; ++pops) {
    if (pops >= max_pops || charged >= max_pops - pops) {
      // The step's budget is spent: the search goes on at the next resume().
      resident_pages_ = std::max(resident_pages_, used_);
      run_.partial = r;
      run_.best = best;
      run_.reached = reached;
      run_.limit = limit;
      return false;
    }
    std::uint32_t s;
    if (use_ring) {
      if (ring_.empty() || ring_.lower() >= best) break;
      s = ring_.pop();
    } else {
      if (open_.empty() || open_.top().key >= best) break;
      s = open_.pop().node;
    }
    meta[s] = static_cast<std::uint8_t>(meta[s] | kClosed);
    const std::uint32_t local = s & local_mask;
    const PageOrigin& o = origin[s >> shift];
    const int slot = static_cast<int>(local >> (2 * kTileShift));
    const int x = o.x + static_cast<int>(local & static_cast<std::uint32_t>(tmask));
    const int y = o.y + static_cast<int>((local >> kTileShift) & static_cast<std::uint32_t>(tmask));
    const std::uint32_t u = static_cast<std::uint32_t>(y) * stride + static_cast<std::uint32_t>(x);
    const int k = move_slice[slot];
    const double gu = g[s];
    if (u == t || gu + h_of(x, y, u) >= best) continue;
    ++r.expanded;
    run_.min_x = std::min(run_.min_x, x);
    run_.max_x = std::max(run_.max_x, x);
    run_.min_y = std::min(run_.min_y, y);
    run_.max_y = std::max(run_.max_y, y);
    if (r.expanded >= run_.next_enclosure && best == CostField::kInfinity) {
      // Still searching, all expansions so far within a box that fits EnclosureTest's window:
      // is the robot shut in there? (Everything expanded lies in the start's component, so the
      // window is placed around it; a component larger than the box may still leave the window,
      // so a test that finds the window's ring is tried again later, around a larger box.)
      run_.next_enclosure = r.expanded * kEnclosureGrowth;
      constexpr int kWin = EnclosureTest::kSize;
      const int span_x = run_.max_x - run_.min_x + 1;
      const int span_y = run_.max_y - run_.min_y + 1;
      if (span_x <= kWin - 2 && span_y <= kWin - 2 && run_.enclosure_tries < kEnclosureTries) {
        ++run_.enclosure_tries;
        if (enclosure_.enclosed(lg, run_.min_x - (kWin - span_x) / 2, run_.min_y - (kWin - span_y) / 2)) {
          shut_in_ = true;
          break;  // best is infinite: ends unreachable below
        }
      }
    }
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
      relax(x + kMoveDx[m], y + kMoveDy[m], slot, gu + cost[m][cu][cv], static_cast<std::uint8_t>(m));
    }
    if (m_count > 1) {
      // The current slice is free at u (tight); turning may ask for more room, except where
      // the robot already stands: there the body's own room is enough (it may have stopped
      // close to something, and must be able to turn away).
      const bool grown = own_turns && u != start_index;
      const int up = (slot + 1) % m_count;
      const int down = (slot + m_count - 1) % m_count;
      const int n_up = (move_slice[up] - k + k_count) % k_count;
      const int n_down = (k - move_slice[down] + k_count) % k_count;
      if (arc_free(lg, grown, u, k, n_up, +1)) relax(x, y, up, gu + n_up * turn, kTurnedUp);
      if (arc_free(lg, grown, u, k, n_down, -1)) relax(x, y, down, gu + n_down * turn, kTurnedDown);
    }
  }
  run_.active = false;
  resident_pages_ = std::max(resident_pages_, used_);
  if (limit) {
    r.status = PlanStatus::SearchLimit;
    out = r;
    return true;
  }
  const bool found = best != CostField::kInfinity;
  if (!found) {
    out = r;  // Unreachable
    return true;
  }

  // Walk back from the goal state, listing every slice a turn passes.
  int orth = 0;
  int diag = 0;
  std::uint32_t s = reached;
  r.cost = g[s];
  for (;;) {
    const std::uint32_t local = s & local_mask;
    const PageOrigin& o = origin[s >> shift];
    const int slot = static_cast<int>(local >> (2 * kTileShift));
    int x = o.x + static_cast<int>(local & static_cast<std::uint32_t>(tmask));
    int y = o.y + static_cast<int>((local >> kTileShift) & static_cast<std::uint32_t>(tmask));
    const int k = move_slice[slot];
    path_.push_back({x - 1, y - 1, k});
    const int p = meta[s] & kParentMask;
    if (p == kStartState) break;
    int from_slot = slot;
    int dir = 0;  // slice step walking back: -1 (we turned up), +1 (we turned down)
    int stop = -1;
    if (p < 8) {
      (p < 4 ? orth : diag) += 1;
      x -= kMoveDx[p];
      y -= kMoveDy[p];
    } else if (p == kTurnedUp || p == kSeedUp) {
      dir = -1;
      from_slot = (slot + m_count - 1) % m_count;
      stop = p == kSeedUp ? s0 : move_slice[from_slot];
    } else {
      dir = +1;
      from_slot = (slot + 1) % m_count;
      stop = p == kSeedDown ? s0 : move_slice[from_slot];
    }
    if (dir != 0) {
      for (int j = (k + dir + k_count) % k_count; j != stop; j = (j + dir + k_count) % k_count)
        path_.push_back({x - 1, y - 1, j});
      if (p == kSeedUp || p == kSeedDown) {
        path_.push_back({x - 1, y - 1, s0});
        break;
      }
    }
    s = id_in(tile_of(x, y).page, x, y, from_slot);
  }
  std::reverse(path_.begin(), path_.end());
  r.status = PlanStatus::Found;
  r.length = static_cast<double>(orth) + kSqrt2 * static_cast<double>(diag);
  out = r;
  return true;
}

}  // namespace robuter::plan
