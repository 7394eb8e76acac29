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
  // A tile entry per slot group: at most one per move slot (a power of two of them).
  const std::size_t groups = std::size_t{1} << std::max(log2_ceil(static_cast<std::size_t>(k)) - kPageSlotShift, 0);
  const auto tiles = static_cast<std::size_t>(tiles_x_) * static_cast<std::size_t>(tiles_y) * groups;
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
  if (end_extra_.size() < kk) end_extra_.resize(kk, 0.0);
  if (slot_turn_.size() < kk) slot_turn_.resize(kk, 0.0);
  if (seed_cost_.size() < kk) seed_cost_.resize(kk, 0.0);
  if (chain_.capacity() < budget) {
    memo_.reset(new std::uint8_t[budget]);  // read only where a tree state was written
    chain_.reserve(budget);
    epoch_ = 0;
  }
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
                          const CostField* heuristic, const SliceBits* turn_room, PlanResult& out,
                          HeadingSearch* tree) {
  PlanResult r;
  path_.clear();
  used_ = 0;
  run_.active = false;
  shut_in_ = false;
  kept_ = false;
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

  const int m_count = prepare(slices, options);
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
  run_ = Run{.in = {slices, start, goal, options, costs, heuristic, turn_room},
             .m_count = m_count,
             .use_ring = use_ring,
             .active = true,
             .tree = tree};
  std::fill_n(end_extra_.begin(), m_count, 0.0);  // the goal cell at any heading
  return false;
}

void HeadingSearch::begin_backward(std::span<const PassGrid* const> slices, CellPose robot, Cell goal,
                                   const HeadingOptions& options, const CostModel& costs,
                                   const CostField* goal_field, const SliceBits* turn_room) {
  path_.clear();
  used_ = 0;
  run_ = Run{};
  shut_in_ = false;
  kept_ = false;
  const int k_count = static_cast<int>(slices.size());
  const int m_count = prepare(slices, options);
  pages_ = std::min(pages_, kTreeStateBudget >> page_shift_);  // the tree's share of the pool
  const PassGrid& g0 = *slices[0];
  robot.slice = ((robot.slice % k_count) + k_count) % k_count;
  const double turn = std::max(options.rotation_step_cost, 0.0);
  const double max_edge =
      std::max(kSqrt2 * std::max(1.0, costs.unknown_cost), turn * std::max(k_count - 1, 1));
  const Cell rc{robot.x, robot.y};
  run_.in.goal = rc;
  run_.in.heuristic = goal_field;
  robot_h_ = goal_field ? goal_field->cost_at(g0.index(rc)) : 0.0;
  for (int j = 0; j < m_count; ++j) {  // the ring distance from the robot's slice, in turn steps
    const int d = std::abs(move_slice_[static_cast<std::size_t>(j)] - robot.slice);
    slot_turn_[static_cast<std::size_t>(j)] = std::min(d, k_count - d) * turn;
  }
  const double h0 = toward_robot(goal.x + 1, goal.y + 1, g0.index(goal));
  open_.clear();
  const bool use_ring = !options.heap && h0 != CostField::kInfinity && ring_.reset(kBucketWidth, max_edge, h0);
  // The seeds: every move slot at the goal; the end: the robot's cell. The shut-in proof floods
  // from a robot, not a goal: never here.
  run_ = Run{.in = {slices, CellPose{goal.x, goal.y, 0}, rc, options, costs, goal_field, turn_room},
             .m_count = m_count,
             .use_ring = use_ring,
             .active = m_count > 0 && h0 != CostField::kInfinity,
             .next_enclosure = ~std::uint32_t{0},
             .backward = true};
  goal_cell_ = g0.index(goal);
  // The end cell's extra cost per slot: the robot's turn from its slice in the body's room.
  const LeanGraph lg = graph(slices, g0.index(rc), robot.slice, g0.index(rc));
  start_turns(lg, turn, end_extra_.data());
  kept_ = !run_.active;  // nothing to search: an empty tree, exhausted
  bound_ = CostField::kInfinity;
  settle_ = CostField::kInfinity;
}

int HeadingSearch::prepare(std::span<const PassGrid* const> slices, const HeadingOptions& options) {
  const int k_count = static_cast<int>(slices.size());
  const PassGrid& g0 = *slices[0];
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
  const int all_slot_bits = log2_ceil(static_cast<std::size_t>(std::max(m_count, 1)));
  slot_bits_ = std::min(kPageSlotShift, all_slot_bits);
  group_shift_ = all_slot_bits - slot_bits_;
  page_shift_ = 2 * kTileShift + slot_bits_;
  pages_ = std::min(budget_ >> page_shift_, kMaxPages);
  return m_count;
}

LeanGraph HeadingSearch::graph(std::span<const PassGrid* const> slices, std::uint32_t start, int start_slice,
                               std::uint32_t end) const {
  const PassGrid& g0 = *slices[0];
  const int k_count = static_cast<int>(slices.size());
  const SliceBits* tr = run_.in.turn_room;
  const bool own_turns = tr != nullptr && tr->slices == k_count;
  return LeanGraph{cls_of_.data(), k_count, g0.stride, g0.height + 2, move_slice_.data(), run_.m_count,
                   slot_of_.data(), allowed_.data(), own_turns ? tr->bits.data() : nullptr,
                   own_turns ? tr->words : 1, start, start_slice, end};
}

void HeadingSearch::start_turns(const LeanGraph& lg, double turn, double* cost) {
  for (int j = 0; j < lg.slots; ++j) cost[j] = CostField::kInfinity;
  const int s0 = lg.start_slice;
  if (lg.slot_of[s0] >= 0) cost[lg.slot_of[s0]] = 0.0;
  // Up and down the ring from the robot's slice, while the body's own room lets it turn.
  for (int dir = -1; dir <= 1; dir += 2)
    for (int n = 1; n < lg.slices; ++n) {
      if (!arc_free(lg, false, lg.start, s0, n, dir)) break;
      const int j = ((s0 + dir * n) % lg.slices + lg.slices) % lg.slices;
      const int slot = lg.slot_of[j];
      if (slot >= 0) cost[slot] = std::min(cost[slot], n * turn);
    }
}

bool HeadingSearch::resume(std::uint32_t max_pops, PlanResult& out) {
  if (!run_.active) return true;
  if (run_.settling) return settle_step(std::size_t{max_pops} * kSettleStatesPerPop, out);
  // The search's inputs, and what begin() derived from them, as locals: the loop below reads
  // them from registers, not through `this` (its writes to meta_ may alias any member).
  const std::span<const PassGrid* const> slices = run_.in.slices;
  const CellPose start = run_.in.start;
  const Cell goal = run_.in.goal;
  const HeadingOptions& options = run_.in.options;
  const CostModel& costs = run_.in.costs;
  const CostField* const heuristic = run_.in.heuristic;
  const SliceBits* const turn_room = run_.in.turn_room;
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
  auto h_of = [&](int x, int y, std::uint32_t cell) {
    return run_.backward ? toward_robot(x, y, cell) : heuristic_at(heuristic, goal, x, y, cell);
  };
  const double turn = std::max(options.rotation_step_cost, 0.0);
  double* g = g_.get();
  std::uint8_t* meta = meta_.get();
  TileEntry* tiles = tiles_.data();
  PageOrigin* origin = origin_.data();
  const int tiles_x = tiles_x_;
  constexpr int tmask = (1 << kTileShift) - 1;
  const int group_shift = group_shift_;
  const int slot_bits = slot_bits_;
  const int slot_mask = (1 << slot_bits) - 1;
  // entry_of() and state_in() with this search's values in registers.
  auto tile_of = [&](int x, int y, int slot) -> TileEntry& {
    return tiles[entry_index(tiles_x, group_shift, slot_bits, x, y, slot)];
  };
  auto id_in = [&](std::uint32_t page, int x, int y, int slot) {
    return state_index(shift, slot_bits, page, x, y, slot);
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
  // kFirstTouchPops per 512 states (4 KB of costs), whatever a page holds.
  const std::uint32_t first_touch = std::max<std::uint32_t>((kFirstTouchPops << shift) >> 9, 1);
  std::uint32_t charged = 0;
  double best = run_.best;
  std::uint32_t reached = run_.reached;
  std::uint32_t reached_tree = run_.reached_tree;
  bool limit = run_.limit;

  const bool backward = run_.backward;
  HeadingSearch* const tree = run_.tree;
  const double* end_extra = end_extra_.data();
  // The heuristic of a state: the cell's (`hc`), raised by the kept tree's bound when there is
  // one; `settled` gets the tree state when the bound is its exact value.
  const double* slot_turn = slot_turn_.data();
  auto h_state = [&](int x, int y, std::uint32_t cell, int slot, double hc, std::uint32_t& settled) {
    settled = kNoState;
    if (backward) return hc + slot_turn[slot];  // toward_robot() with the slot's part
    if (tree == nullptr) return hc;
    return std::max(hc, tree->tree_bound(x, y, slot, cell, settled));
  };

  auto relax = [&](int x, int y, int slot, double ng, std::uint8_t how) {
    const std::uint32_t cell = static_cast<std::uint32_t>(y) * stride + static_cast<std::uint32_t>(x);
    TileEntry& te = tile_of(x, y, slot);
    double hc = -1.0;
    if (te.stamp != gen_) {
      hc = h_of(x, y, cell);
      if (hc == CostField::kInfinity) return;  // the relaxation cannot reach the end from here
      if (used_ == pages_) {
        limit = true;  // the pool is spent: the search cannot finish exactly
        return;
      }
      te.stamp = gen_;
      if (used_ >= resident) charged += first_touch;
      te.page = static_cast<std::uint16_t>(used_++);
      origin[te.page] = PageOrigin{x & ~tmask, y & ~tmask, slot & ~slot_mask};
      std::fill_n(meta + (static_cast<std::size_t>(te.page) << shift), std::size_t{1} << shift,
                  std::uint8_t{0});
      if (backward)  // tree_valid()'s memo: no tag yet
        std::fill_n(memo_.get() + (static_cast<std::size_t>(te.page) << shift), std::size_t{1} << shift,
                    std::uint8_t{0});
    }
    const std::uint32_t s = id_in(te.page, x, y, slot);
    std::uint8_t& mt_s = meta[s];
    const bool seen = (mt_s & kSeen) != 0;
    if (seen && !(ng < g[s] - 1e-9 && (use_ring || !(mt_s & kClosed)))) return;
    if (hc < 0.0) hc = h_of(x, y, cell);
    if (hc == CostField::kInfinity) return;
    std::uint32_t settled = kNoState;
    const double h = h_state(x, y, cell, slot, hc, settled);
    if (!seen) {
      g[s] = ng;
      mt_s = static_cast<std::uint8_t>(kSeen | how);
      if (use_ring) ring_.push(s, ng + h);
      else open_.push(s, ng + h, static_cast<float>(h));
    } else {
      if (mt_s & kClosed) {
        ring_.push(s, ng + h);  // reopened (ring only): its first expansion came a little early
      } else if (use_ring) {
        ring_.lower_key(s, g[s] + h, ng + h);
      } else {
        open_.decrease(s, ng + h, static_cast<float>(h));
      }
      g[s] = ng;
      mt_s = static_cast<std::uint8_t>(kSeen | how);
    }
    if (cell == t && ng + end_extra[slot] < best) {
      best = ng + end_extra[slot];
      reached = s;
      reached_tree = kNoState;
    }
    // A state of the kept tree whose path still holds: the plan may end here.
    if (settled != kNoState && ng + h < best && tree->tree_valid(settled)) {
      best = ng + h;
      reached = s;
      reached_tree = settled;
    }
  };

  const int s0 = start.slice;
  const LeanGraph lg{cls_of, k_count, g0.stride, g0.height + 2, move_slice, m_count, slot_of, allowed,
                     own_turns ? turn_room->bits.data() : nullptr, own_turns ? turn_room->words : 1,
                     start_index, s0, t};
  if (!run_.seeded) {
    run_.seeded = true;
    if (tree != nullptr) tree->new_epoch();
    if (backward) {
      // Every move slot free at the goal, at cost 0.
      for (int j = 0; j < m_count; ++j)
        if (cls_of[move_slice[j]][start_index] != kBlocked) relax(sx, sy, j, 0.0, kStartState);
    } else {
      // The robot's own slot, and every move slot it can turn to where it stands before it
      // moves (the body's own room: it may have stopped close to something, and must be able
      // to turn away), the nearest way round.
      double* seed = seed_cost_.data();
      start_turns(lg, turn, seed);
      for (int j = 0; j < m_count; ++j) {
        if (seed[j] == CostField::kInfinity) continue;
        if (move_slice[j] == s0) {
          relax(sx, sy, j, 0.0, kStartState);
          continue;
        }
        const int up = (move_slice[j] - s0 + k_count) % k_count;  // slice steps turning up
        const bool via_up = up * turn == seed[j] && arc_free(lg, false, start_index, s0, up, +1);
        relax(sx, sy, j, seed[j], via_up ? kSeedUp : kSeedDown);
      }
    }
  }
  double expanding = 0.0;  // key of the state being expanded (the tree's settle level if the pool runs out)
  for (std::uint32_t pops = 0; !limit; ++pops) {
    if (pops >= max_pops || charged >= max_pops - pops) {
      // The step's budget is spent: the search goes on at the next resume().
      resident_pages_ = std::max(resident_pages_, used_);
      run_.partial = r;
      run_.best = best;
      run_.reached = reached;
      run_.reached_tree = reached_tree;
      run_.limit = limit;
      return false;
    }
    // A forward search ends when no queued key is below the best end; the kept tree's when every
    // queued key exceeds it (by twice settle_slack(): keys equal to the robot's cost but for
    // rounding are settled too), so that its ties are settled.
    const double last = backward ? best + tree_margin(best) + 2.0 * settle_slack(best) : best;  // keys up to this are expanded
    if (backward && best != CostField::kInfinity && !run_.proven &&
        (use_ring ? ring_.empty() || ring_.lower() >= best : open_.empty() || open_.top().key >= best))
      run_.proven = true;  // the robot's cost is optimal, its tree path exact
    std::uint32_t s;
    if (use_ring) {
      if (ring_.empty() || (backward ? ring_.lower() > last : ring_.lower() >= best)) break;
      s = ring_.pop();
    } else {
      if (open_.empty() || (backward ? open_.top().key > last : open_.top().key >= best)) break;
      s = open_.pop().node;
    }
    meta[s] = static_cast<std::uint8_t>(meta[s] | kClosed);
    int x, y, slot;
    place_in(s & local_mask, origin[s >> shift], x, y, slot);
    const std::uint32_t u = static_cast<std::uint32_t>(y) * stride + static_cast<std::uint32_t>(x);
    const int k = move_slice[slot];
    const double gu = g[s];
    {
      std::uint32_t settled = kNoState;
      const double f = gu + h_state(x, y, u, slot, h_of(x, y, u), settled);
      if (backward ? f > last : (u == t || f >= best)) continue;
      expanding = f;
    }
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
      if (!mt.passable(cls, u, m)) continue;
      const std::uint8_t cv = cls[u + static_cast<std::uint32_t>(mt.step[m])];
      relax(x + kMoveDx[m], y + kMoveDy[m], slot, gu + cost[m][cu][cv], static_cast<std::uint8_t>(m));
    }
    if (m_count > 1) {
      // The current slice is free at u (tight); turning may ask for more room.
      const bool grown = own_turns;  // the start's own turns were seeded
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
  if (backward) {
    // Every key up to the settle level is final: the margin past the robot's cost, or, if the
    // pool ran out after the robot was reached, just below the key being expanded then (every
    // state below it was expanded whole). Out of pool before the robot: no tree.
    const bool reached_robot = best != CostField::kInfinity;
    const bool keep = !limit || run_.proven;  // kept_ stays false until settle_step() ends
    bound_ = best;
    settle_ = limit ? std::min(best + tree_margin(best), expanding - 2.0 * settle_slack(expanding))
                    : best + tree_margin(best);
    r.status = !keep ? PlanStatus::SearchLimit : reached_robot ? PlanStatus::Found : PlanStatus::Unreachable;
    r.cost = best;
    run_.partial = r;  // expanded_so_far(): the whole tree
    if (!keep) {
      out = r;
      return true;
    }
    // Kept: its states are settled in the next steps (settle_step), then it serves.
    run_.active = true;
    run_.settling = true;
    run_.settle_page = 0;
    run_.reached = reached;
    return false;
  }
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
  r.cost = best;
  walk_back(reached, path_);
  std::reverse(path_.begin(), path_.end());
  if (reached_tree != kNoState) {
    const int p = meta[reached] & kParentMask;  // the move into the end state, if it was one
    tree->append_tree_path(reached_tree, p < 8 ? p : -1, path_);
  }
  int orth = 0, diag = 0;
  for (std::size_t i = 1; i < path_.size(); ++i) {
    const int dx = path_[i].x - path_[i - 1].x, dy = path_[i].y - path_[i - 1].y;
    if (dx != 0 || dy != 0) ++(dx != 0 && dy != 0 ? diag : orth);
  }
  r.status = PlanStatus::Found;
  r.length = static_cast<double>(orth) + kSqrt2 * static_cast<double>(diag);
  out = r;
  return true;
}

}  // namespace robuter::plan
