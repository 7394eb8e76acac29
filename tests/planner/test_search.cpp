// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the 2D searches: optimal A*, the thesis' BFS, no corner cutting, failures, unknown cost.
#include <gtest/gtest.h>

#include <random>

#include "modules/planner/lib/grid_search.hpp"
#include "tests/planner/test_util.hpp"

namespace robuter::plan {
namespace {

using test::grid_from_art;

// Why: every step of a returned path must be a legal move of the grid.
void expect_legal(const PassGrid& g, const std::vector<Cell>& path) {
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const Cell a = path[i], b = path[i + 1];
    const int dx = b.x - a.x, dy = b.y - a.y;
    ASSERT_TRUE(std::abs(dx) <= 1 && std::abs(dy) <= 1 && (dx || dy));
    ASSERT_NE(g.at(b), kBlocked);
    if (dx && dy) {
      EXPECT_NE(g.at({a.x + dx, a.y}), kBlocked) << "corner cut at step " << i;
      EXPECT_NE(g.at({a.x, a.y + dy}), kBlocked) << "corner cut at step " << i;
    }
  }
}

TEST(GridSearch, NoCornerCuttingBothModes) {
  // The only way from S (0,0) to G (1,1) diagonally squeezes between two blocked cells.
  const PassGrid g = grid_from_art({
      ".#.",
      "#..",
      "...",
  });
  // rows top first: (0,2)='.', (1,2)='#'; (0,1)='#'; (0,0)='.'
  GridSearch s(3, 3);
  for (SearchMode mode : {SearchMode::Optimal, SearchMode::Bfs}) {
    const PlanResult r = s.find(g, {0, 0}, {1, 1}, mode);
    ASSERT_TRUE(r.found());
    EXPECT_NEAR(r.length, 2.0, 1e-12);  // two orthogonal moves, not the cut diagonal
    expect_legal(g, s.path());
  }
  // (0,2) is reachable only by the diagonal (1,1) -> (0,2), which cuts both corners.
  for (SearchMode mode : {SearchMode::Optimal, SearchMode::Bfs})
    EXPECT_EQ(s.find(g, {0, 0}, {0, 2}, mode).status, PlanStatus::Unreachable);
}

TEST(GridSearch, DiagonalAllowedWhenBothSidesFree) {
  const PassGrid g = grid_from_art({
      "...",
      "...",
      "...",
  });
  GridSearch s(3, 3);
  for (SearchMode mode : {SearchMode::Optimal, SearchMode::Bfs}) {
    const PlanResult r = s.find(g, {0, 0}, {2, 2}, mode);
    ASSERT_TRUE(r.found());
    EXPECT_NEAR(r.length, 2 * kSqrt2, 1e-12);
    EXPECT_EQ(s.path().size(), 3u);
  }
}

TEST(GridSearch, BfsMinimisesMovesNotLength) {
  // BFS (unit moves) may return a longer path than A* with octile costs.
  const PassGrid g = grid_from_art({
      "......",
      "......",
      "......",
  });
  GridSearch s(6, 3);
  const PlanResult bfs = s.find(g, {0, 0}, {5, 2}, SearchMode::Bfs);
  const PlanResult opt = s.find(g, {0, 0}, {5, 2}, SearchMode::Optimal);
  ASSERT_TRUE(bfs.found() && opt.found());
  EXPECT_NEAR(opt.length, 3 + 2 * kSqrt2, 1e-12);
  EXPECT_GE(bfs.length, opt.length - 1e-12);
  EXPECT_EQ(bfs.expanded > 0, true);
}

TEST(GridSearch, UnreachableGoal) {
  const PassGrid g = grid_from_art({
      "..#..",
      "..#..",
      "..#..",
  });
  GridSearch s(5, 3);
  for (SearchMode mode : {SearchMode::Optimal, SearchMode::Bfs}) {
    const PlanResult r = s.find(g, {0, 0}, {4, 2}, mode);
    EXPECT_EQ(r.status, PlanStatus::Unreachable);
    EXPECT_TRUE(s.path().empty());
  }
}

TEST(GridSearch, GoalOrStartOutsideOrBlocked) {
  const PassGrid g = grid_from_art({
      "...",
      ".#.",
      "...",
  });
  GridSearch s(3, 3);
  EXPECT_EQ(s.find(g, {0, 0}, {3, 0}, SearchMode::Optimal).status, PlanStatus::GoalOutside);
  EXPECT_EQ(s.find(g, {0, 0}, {0, -1}, SearchMode::Bfs).status, PlanStatus::GoalOutside);
  EXPECT_EQ(s.find(g, {-1, 0}, {0, 0}, SearchMode::Optimal).status, PlanStatus::StartOutside);
  EXPECT_EQ(s.find(g, {1, 1}, {0, 0}, SearchMode::Optimal).status, PlanStatus::StartBlocked);
  EXPECT_EQ(s.find(g, {0, 0}, {1, 1}, SearchMode::Optimal).status, PlanStatus::GoalBlocked);
  const PlanResult same = s.find(g, {2, 2}, {2, 2}, SearchMode::Optimal);
  ASSERT_TRUE(same.found());
  EXPECT_EQ(same.length, 0.0);
  EXPECT_EQ(s.path().size(), 1u);
}

TEST(GridSearch, UnknownCellsFreeByDefaultCostlyOnRequest) {
  // A short way through unknown cells and a longer way around through known free cells.
  const PassGrid g = grid_from_art({
      ".......",
      ".#####.",
      ".#####.",
      "???????",
  });
  GridSearch s(7, 4);
  const PlanResult plain = s.find(g, {0, 0}, {6, 0}, SearchMode::Optimal);
  ASSERT_TRUE(plain.found());
  EXPECT_NEAR(plain.length, 6.0, 1e-12);  // straight through the unknown row
  CostModel careful;
  careful.unknown_cost = 3.0;
  const PlanResult detour = s.find(g, {0, 0}, {6, 0}, SearchMode::Optimal, careful);
  ASSERT_TRUE(detour.found());
  EXPECT_GT(detour.length, 6.0);
  EXPECT_LT(detour.cost, 3.0 * 6.0);
}

TEST(GridSearch, EnginesAgreeWithUnknownCosts) {
  // Buckets (moderate unknown cost) and the heap (huge unknown cost) against each other and
  // against a field computed by Dijkstra from the goal.
  std::mt19937 rng(9);
  const int w = 40, h = 25;
  PassGrid g(w, h);
  std::uniform_int_distribution<int> pick(0, 9);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int c = pick(rng);
      g.set({x, y}, c < 2 ? kBlocked : c < 5 ? kUnknown : kFree);
    }
  g.set({0, 0}, kFree);
  GridSearch s(w, h);
  for (double u : {1.0, 1.7, 3.0, 1e4}) {
    const CostModel costs{u};
    for (int y = 0; y < h; y += 3)
      for (int x = 0; x < w; x += 3) {
        if (g.at({x, y}) == kBlocked) continue;
        s.set_engine(GridSearch::Engine::Heap);
        const PlanResult a = s.find(g, {0, 0}, {x, y}, SearchMode::Optimal, costs);
        s.set_engine(GridSearch::Engine::Auto);
        const PlanResult b = s.find(g, {0, 0}, {x, y}, SearchMode::Optimal, costs);
        ASSERT_EQ(a.status, b.status);
        if (a.found()) {
          EXPECT_NEAR(a.cost, b.cost, 1e-9 * a.cost) << u << " " << x << "," << y;
        }
      }
  }
}

TEST(GridSearch, AutoPicksJumpPointsForWallsBucketsForScatteredCells) {
  PassGrid rooms(64, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) rooms.set({x, y}, (x % 16 == 0 && y % 8 != 4) ? kBlocked : kFree);
  PassGrid random(64, 64);
  std::mt19937 rng(1);
  std::bernoulli_distribution b(0.2);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) random.set({x, y}, b(rng) ? kBlocked : kFree);
  GridSearch s(64, 64);
  EXPECT_LT(s.scattered_fraction(rooms), GridSearch::kScatteredLimit);
  EXPECT_GT(s.scattered_fraction(random), GridSearch::kScatteredLimit);
}

TEST(GridSearch, AStarMatchesDijkstraOnRandomGrids) {
  // Reference: plain Dijkstra (A* with h = 0 is not exposed; use BFS-free brute force).
  std::mt19937 rng(7);
  for (int trial = 0; trial < 8; ++trial) {
    const int w = 30, h = 20;
    PassGrid g(w, h);
    std::bernoulli_distribution blocked(0.3);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) g.set({x, y}, blocked(rng) ? kBlocked : kFree);
    g.set({0, 0}, kFree);
    // Bellman-Ford style relaxation as the reference.
    std::vector<double> d(g.stored(), 1e18);
    const MoveTable mt(g.stride);
    d[g.index({0, 0})] = 0;
    for (bool changed = true; changed;) {
      changed = false;
      for (std::uint32_t u = 0; u < g.stored(); ++u) {
        if (g.cls[u] == kBlocked || d[u] >= 1e17) continue;
        for (int m = 0; m < 8; ++m) {
          const std::uint32_t v = u + static_cast<std::uint32_t>(mt.step[m]);
          if (v >= g.stored() || g.cls[v] == kBlocked) continue;
          if (m >= 4 && (g.cls[u + static_cast<std::uint32_t>(mt.side_a[m])] == kBlocked ||
                         g.cls[u + static_cast<std::uint32_t>(mt.side_b[m])] == kBlocked))
            continue;
          const double nd = d[u] + (m < 4 ? 1.0 : kSqrt2);
          if (nd < d[v] - 1e-12) d[v] = nd, changed = true;
        }
      }
    }
    GridSearch s(w, h);
    for (auto engine : {GridSearch::Engine::Auto, GridSearch::Engine::JumpPoints,
                        GridSearch::Engine::Buckets, GridSearch::Engine::Heap}) {
      s.set_engine(engine);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          if (g.at({x, y}) == kBlocked) continue;
          const PlanResult r = s.find(g, {0, 0}, {x, y}, SearchMode::Optimal);
          const double ref = d[g.index({x, y})];
          if (ref >= 1e17) {
            EXPECT_EQ(r.status, PlanStatus::Unreachable);
          } else {
            ASSERT_TRUE(r.found());
            EXPECT_NEAR(r.length, ref, 1e-9) << static_cast<int>(engine);
            expect_legal(g, s.path());
          }
        }
    }
  }
}

}  // namespace
}  // namespace robuter::plan
