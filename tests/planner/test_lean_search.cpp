// SPDX-License-Identifier: GPL-3.0-or-later
// The lean (cell, move slice) search against the full (cell, slice) graph: same costs, valid paths.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <span>
#include <vector>

#include "modules/planner/lib/cost_field.hpp"
#include "modules/planner/lib/heading_search.hpp"
#include "tests/planner/reference_heading_search.hpp"
#include "tests/planner/test_util.hpp"
#include "tests/support/sample.hpp"

namespace robuter::plan {
namespace {

// A random slice stack: one base map of classes (free or unknown), each slice blocks more cells.
struct Stack {
  std::vector<PassGrid> slices;  // the body's room per slice
  std::vector<PassGrid> turns;   // room to turn per slice (in half the stacks within the body's)
  PassGrid relaxed;              // free where any slice is (an admissible relaxation)
  std::vector<const PassGrid*> slice_ptrs;  // pointers to slices
  std::vector<const PassGrid*> turn_ptrs;   // pointers to turns (the reference search's form)
  SliceBits turn_bits;                       // turns as the planner keeps them: bit set = blocked
};

Stack random_stack(std::mt19937& rng, int w, int h, int k, double density) {
  Stack st;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  PassGrid base(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      base.set({x, y}, static_cast<std::uint8_t>(u(rng) < density ? kBlocked : (u(rng) < 0.3 ? kUnknown : kFree)));
  st.slices.assign(static_cast<std::size_t>(k), base);
  st.turns.assign(static_cast<std::size_t>(k), base);
  st.relaxed = PassGrid(w, h);
  const bool superset = u(rng) < 0.5;  // as the planner's grown bodies
  for (int s = 0; s < k; ++s)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        PassGrid& g = st.slices[static_cast<std::size_t>(s)];
        if (u(rng) < 0.5 * density) g.set({x, y}, kBlocked);
        PassGrid& t = st.turns[static_cast<std::size_t>(s)];
        const bool blocked = (superset && g.at({x, y}) == kBlocked) || u(rng) < 0.3 * density;
        t.set({x, y}, blocked ? std::uint8_t{kBlocked} : base.at({x, y}));
        if (g.at({x, y}) != kBlocked) st.relaxed.set({x, y}, base.at({x, y}));
      }
  for (const PassGrid& g : st.slices) st.slice_ptrs.push_back(&g);
  for (const PassGrid& g : st.turns) st.turn_ptrs.push_back(&g);
  st.turn_bits = test::slice_bits_of(st.turns);
  return st;
}

// Why: checks that a path is a walk of the full graph from start to goal and returns its cost
// (-1 if a step is not an edge).
double walk_cost(const Stack& st, const std::vector<CellPose>& path, CellPose start, Cell goal,
                 const HeadingOptions& opt, const CostModel& costs, bool with_turns) {
  const int k = static_cast<int>(st.slices.size());
  if (path.empty() || !(path.front() == start) || path.back().x != goal.x || path.back().y != goal.y)
    return -1.0;
  const auto table = costs.table();
  double total = 0.0;
  bool moved = false;  // a grid move made: the start's body room no longer serves turns
  for (std::size_t i = 1; i < path.size(); ++i) {
    const CellPose a = path[i - 1];
    const CellPose b = path[i];
    const PassGrid& ga = st.slices[static_cast<std::size_t>(a.slice)];
    if (a.x == b.x && a.y == b.y) {
      const int d = (b.slice - a.slice + k) % k;
      if (d != 1 && d != k - 1) return -1.0;
      const bool at_start = !moved && a.x == start.x && a.y == start.y;
      const auto& room = with_turns && !at_start ? st.turns : st.slices;
      const Cell c{a.x, a.y};
      if (room[static_cast<std::size_t>(a.slice)].at(c) == kBlocked ||
          room[static_cast<std::size_t>(b.slice)].at(c) == kBlocked ||
          st.slices[static_cast<std::size_t>(b.slice)].at(c) == kBlocked)
        return -1.0;
      total += opt.rotation_step_cost;
      continue;
    }
    if (a.slice != b.slice) return -1.0;
    moved = true;
    int m = -1;
    for (int j = 0; j < 8; ++j)
      if (b.x - a.x == kMoveDx[j] && b.y - a.y == kMoveDy[j]) m = j;
    if (m < 0 || !(allowed_moves(a.slice, k, opt.motion) & (1u << m))) return -1.0;
    const std::uint8_t ca = ga.at({a.x, a.y});
    const std::uint8_t cb = ga.at({b.x, b.y});
    if (ca == kBlocked || cb == kBlocked) return -1.0;
    if (m >= 4 && (ga.at({a.x + kMoveDx[m], a.y}) == kBlocked || ga.at({a.x, a.y + kMoveDy[m]}) == kBlocked))
      return -1.0;
    total += table[m][ca][cb];
  }
  return total;
}

// The lean search finds exactly the full graph's optimal cost, and a valid path of that cost,
// on random slice stacks: both motion models, with and without turn slices and heuristic, the
// ring and the heap, starts in move and pass-through slices, unreachable goals included. The
// lean search reads the turn slices as bits, the reference as PassGrids.
TEST(LeanHeadingSearch, SameCostsAsTheFullGraphOnRandomStacks) {
  std::mt19937 rng(20261202);
  const int cases = ::robuter::test::sample(3000, 400);
  int found = 0, unreachable = 0, pass_through_starts = 0;
  HeadingSearch lean;
  ReferenceHeadingSearch full;
  CostField field;
  const std::vector<int> ks = {1, 2, 4, 6, 8, 16, 32, 40, 64, 128};  // 40+: turn bits in 2-4 words
  for (int c = 0; c < cases; ++c) {
    const int w = 6 + static_cast<int>(rng() % 18);
    const int h = 6 + static_cast<int>(rng() % 18);
    const int k = ks[rng() % ks.size()];
    const double density = 0.05 + 0.3 * std::uniform_real_distribution<double>(0, 1)(rng);
    const Stack st = random_stack(rng, w, h, k, density);
    HeadingOptions opt;
    opt.motion = rng() % 3 == 0 ? MotionModel::Holonomic : MotionModel::Aligned;
    const double turns[] = {0.0, 0.3, 1.0, 2.7};
    opt.rotation_step_cost = turns[rng() % 4];
    opt.heap = rng() % 4 == 0;
    CostModel costs;
    const double unknown[] = {1.0, 1.0, 2.5, 40.0};
    costs.unknown_cost = unknown[rng() % 4];
    const bool with_turns = rng() % 2 == 0;
    const bool with_h = rng() % 2 == 0;
    CellPose start{static_cast<int>(rng() % static_cast<unsigned>(w)),
                   static_cast<int>(rng() % static_cast<unsigned>(h)), static_cast<int>(rng() % static_cast<unsigned>(k))};
    const Cell goal{static_cast<int>(rng() % static_cast<unsigned>(w)), static_cast<int>(rng() % static_cast<unsigned>(h))};
    const CostField* heur = nullptr;
    if (with_h) {
      field.reserve(w, h);
      field.compute(st.relaxed, goal, costs);
      heur = &field;
    }
    const std::span<const PassGrid* const> turn_span =
        with_turns ? std::span<const PassGrid* const>(st.turn_ptrs) : std::span<const PassGrid* const>();
    const PlanResult a = lean.find(st.slice_ptrs, start, goal, opt, costs, heur, with_turns ? &st.turn_bits : nullptr);
    const PlanResult b = full.find(st.slice_ptrs, start, goal, opt, costs, heur, turn_span);
    SCOPED_TRACE(testing::Message() << "case " << c << " k " << k << " " << w << "x" << h);
    ASSERT_EQ(a.status, b.status);
    if (!a.found()) {
      unreachable += a.status == PlanStatus::Unreachable;
      continue;
    }
    ++found;
    if (allowed_moves(start.slice, k, opt.motion) == 0) ++pass_through_starts;
    ASSERT_NEAR(a.cost, b.cost, 1e-9);
    const double walked = walk_cost(st, lean.path(), start, goal, opt, costs, with_turns);
    ASSERT_GE(walked, 0.0) << "the lean path is not a walk of the full graph";
    ASSERT_NEAR(walked, a.cost, 1e-9);
  }
  EXPECT_GT(found, cases / 5);
  EXPECT_GT(unreachable, cases / 50);
  EXPECT_GT(pass_through_starts, cases / 50);
}

// Why: the planner module runs the search in steps (begin, then resume with a few states each
// activation); any step size must end exactly as one find() does: the same status, cost,
// expansions and path, on random stacks of every kind above.
TEST(LeanHeadingSearch, InStepsEqualsOneSearch) {
  std::mt19937 rng(7102);
  const int cases = ::robuter::test::sample(600, 100);
  int stepped = 0;
  HeadingSearch one, steps;
  CostField field;
  const std::vector<int> ks = {1, 4, 8, 32, 64};
  for (int c = 0; c < cases; ++c) {
    const int w = 6 + static_cast<int>(rng() % 30);
    const int h = 6 + static_cast<int>(rng() % 30);
    const int k = ks[rng() % ks.size()];
    const double density = 0.05 + 0.25 * std::uniform_real_distribution<double>(0, 1)(rng);
    const Stack st = random_stack(rng, w, h, k, density);
    HeadingOptions opt;
    opt.motion = rng() % 3 == 0 ? MotionModel::Holonomic : MotionModel::Aligned;
    opt.rotation_step_cost = rng() % 2 == 0 ? 0.3 : 1.0;
    opt.heap = rng() % 4 == 0;
    CostModel costs;
    costs.unknown_cost = rng() % 3 == 0 ? 2.5 : 1.0;
    const bool with_turns = rng() % 2 == 0;
    const CellPose start{static_cast<int>(rng() % static_cast<unsigned>(w)),
                         static_cast<int>(rng() % static_cast<unsigned>(h)), static_cast<int>(rng() % static_cast<unsigned>(k))};
    const Cell goal{static_cast<int>(rng() % static_cast<unsigned>(w)), static_cast<int>(rng() % static_cast<unsigned>(h))};
    const CostField* heur = nullptr;
    if (rng() % 2 == 0) {
      field.reserve(w, h);
      field.compute(st.relaxed, goal, costs);
      heur = &field;
    }
    const SliceBits* turn = with_turns ? &st.turn_bits : nullptr;
    const PlanResult a = one.find(st.slice_ptrs, start, goal, opt, costs, heur, turn);
    const std::uint32_t budget = 1u + static_cast<std::uint32_t>(rng() % 40);
    PlanResult b;
    int calls = 0;
    if (!steps.begin(st.slice_ptrs, start, goal, opt, costs, heur, turn, b)) {
      do {
        ASSERT_TRUE(steps.pending());
        ASSERT_LT(++calls, 1000000) << "never ends";
      } while (!steps.resume(budget, b));
    }
    EXPECT_FALSE(steps.pending());
    stepped += calls > 1;
    SCOPED_TRACE(testing::Message() << "case " << c << " k " << k << " " << w << "x" << h << " budget " << budget);
    ASSERT_EQ(a.status, b.status);
    ASSERT_EQ(a.expanded, b.expanded);
    if (a.found()) {
      ASSERT_EQ(a.cost, b.cost);
      ASSERT_EQ(a.length, b.length);
      ASSERT_EQ(one.path(), steps.path());
    }
  }
  EXPECT_GT(stepped, cases / 4);  // most searches took several steps
}

// States exist only in move slices: 8 of 32 with the aligned model; a turn from a pass-through
// start slice reaches both neighbouring move slices, and the path lists every slice passed.
TEST(LeanHeadingSearch, PassThroughStartListsEverySlice) {
  PassGrid open(12, 12);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 12; ++x) open.set({x, y}, kFree);
  std::vector<const PassGrid*> stack(32, &open);
  HeadingSearch lean;
  HeadingOptions opt;
  opt.rotation_step_cost = 0.1;
  // Slice 6 lies between move slices 4 (45°) and 8 (90°); the goal is straight up (+y).
  const PlanResult r = lean.find(stack, CellPose{5, 2, 6}, Cell{5, 9}, opt);
  ASSERT_TRUE(r.found());
  EXPECT_NEAR(r.cost, 7.0 + 2 * 0.1, 1e-9);
  const auto& p = lean.path();
  ASSERT_GE(p.size(), 3u);
  EXPECT_EQ(p[0], (CellPose{5, 2, 6}));
  EXPECT_EQ(p[1], (CellPose{5, 2, 7}));
  EXPECT_EQ(p[2], (CellPose{5, 2, 8}));
  EXPECT_EQ(p.back(), (CellPose{5, 9, 8}));
}

// A search that needs more states than its budget ends with SearchLimit (no path, no crash);
// the same search with the default budget finds the path.
TEST(LeanHeadingSearch, BudgetExhaustedIsAClearStatus) {
  PassGrid open(100, 100);
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 100; ++x) open.set({x, y}, kFree);
  open.set({50, 50}, kBlocked);
  std::vector<const PassGrid*> stack(32, &open);
  HeadingSearch small;
  small.reserve(100, 100, 32, 4 * 512);  // 2,048 states
  HeadingOptions opt;
  opt.rotation_step_cost = 0.5;
  const PlanResult r = small.find(stack, CellPose{2, 2, 3}, Cell{97, 90}, opt);
  EXPECT_EQ(r.status, PlanStatus::SearchLimit);
  EXPECT_TRUE(small.path().empty());
  EXPECT_LE(small.pages_used() * small.page_states(), 4u * 512u);
  EXPECT_EQ(to_string(r.status), "search memory exhausted");
  HeadingSearch big;
  const PlanResult ok = big.find(stack, CellPose{2, 2, 3}, Cell{97, 90}, opt);
  EXPECT_TRUE(ok.found());
  EXPECT_LE(big.pages_used() * big.page_states(), big.state_budget());
}

}  // namespace
}  // namespace robuter::plan
