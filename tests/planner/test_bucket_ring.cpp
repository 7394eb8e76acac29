// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the bucket open lists (BucketRing, GridSearch's bucket A*) with non-unit costs.
#include <gtest/gtest.h>

#include <limits>
#include <queue>
#include <random>
#include <vector>

#include "modules/planner/lib/bucket_ring.hpp"
#include "modules/planner/lib/grid_search.hpp"

namespace robuter::plan {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Why: a random grid of free, unknown and blocked cells, the corner (0, 0) free.
PassGrid random_grid(std::mt19937& rng, int w, int h, double blocked, double unknown) {
  PassGrid g(w, h);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double r = u01(rng);
      g.set({x, y}, r < blocked ? kBlocked : r < blocked + unknown ? kUnknown : kFree);
    }
  g.set({0, 0}, kFree);
  return g;
}

// Why: the reference: plain Dijkstra with a binary heap from `s`, the searches' move rules.
std::vector<double> dijkstra(const PassGrid& g, std::uint32_t s, const CostModel& costs) {
  const MoveTable mt(g.stride);
  const auto cost = costs.table();
  std::vector<double> d(g.stored(), kInf);
  using Item = std::pair<double, std::uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> q;
  d[s] = 0.0;
  q.push({0.0, s});
  while (!q.empty()) {
    const auto [du, u] = q.top();
    q.pop();
    if (du > d[u]) continue;
    for (int m = 0; m < 8; ++m) {
      const std::uint32_t v = u + static_cast<std::uint32_t>(mt.step[m]);
      if (g.cls[v] == kBlocked) continue;
      if (m >= 4 && (g.cls[u + static_cast<std::uint32_t>(mt.side_a[m])] == kBlocked ||
                     g.cls[u + static_cast<std::uint32_t>(mt.side_b[m])] == kBlocked))
        continue;
      const double nd = du + cost[m][g.cls[u]][g.cls[v]];
      if (nd < d[v]) d[v] = nd, q.push({nd, v});
    }
  }
  return d;
}

// A node filed below the current bucket (an inconsistent heuristic lowers f along an edge) is
// kept in the current bucket; lower() must still bound every queued key from below, since the
// searches stop when lower() reaches the best goal cost.
TEST(BucketRing, LowerBoundsAKeyFiledBelowTheCurrentBucket) {
  BucketRing ring;
  ring.reserve(4);
  ASSERT_TRUE(ring.reset(0.5, 2.0, 10.0));
  ring.push(0, 10.2);
  EXPECT_EQ(ring.pop(), 0u);  // the ring now stands at bucket [10, 10.5)
  ring.push(1, 9.1);          // below the current bucket
  ring.push(2, 10.4);
  EXPECT_LE(ring.lower(), 9.1);
  ring.lower_key(2, 10.4, 9.6);
  EXPECT_LE(ring.lower(), 9.1);
  ring.pop();
  ring.pop();
  EXPECT_TRUE(ring.empty());
  ring.push(3, 11.3);  // the filed-below keys are gone: the bound follows the buckets again
  EXPECT_EQ(ring.pop(), 3u);
  EXPECT_GE(ring.lower(), 11.0);
}

// A* with the ring as heading_search uses it (reopen a closed node that improves, stop when
// lower() reaches the best goal cost) and an admissible but inconsistent heuristic (the exact
// cost to the goal on a random half of the cells, 0 on the others), unknown cells at 2..46: exact.
TEST(BucketRing, AStarWithAnInconsistentHeuristicIsExact) {
  std::mt19937 rng(16);
  const int w = 40, h = 30;
  int checked = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const PassGrid g = random_grid(rng, w, h, 0.2, 0.35);
    const CostModel costs{2.0 + 4.0 * trial};  // 2 .. 46
    const auto cost = costs.table();
    const MoveTable mt(g.stride);
    const std::uint32_t s = g.index({0, 0});
    const std::vector<double> ref = dijkstra(g, s, costs);
    std::vector<std::uint8_t> zero(g.stored());
    std::bernoulli_distribution half(0.5);
    for (auto& z : zero) z = half(rng) ? 1 : 0;
    BucketRing ring;
    ring.reserve(g.stored());
    std::vector<double> gv(g.stored());
    std::vector<std::uint8_t> state(g.stored());  // 0 unseen, 1 open, 2 closed
    for (int ty = 0; ty < h; ty += 5)
      for (int tx = 0; tx < w; tx += 4) {
        const std::uint32_t t = g.index({tx, ty});
        if (g.cls[t] == kBlocked) continue;
        const std::vector<double> to_goal = dijkstra(g, t, costs);  // moves are symmetric
        auto hf = [&](std::uint32_t v) { return zero[v] || to_goal[v] == kInf ? 0.0 : to_goal[v]; };
        std::fill(state.begin(), state.end(), std::uint8_t{0});
        ASSERT_TRUE(ring.reset(0.5, kSqrt2 * costs.unknown_cost, hf(s)));
        double best = s == t ? 0.0 : kInf;
        gv[s] = 0.0;
        state[s] = 1;
        ring.push(s, hf(s));
        while (!ring.empty() && ring.lower() < best) {
          const std::uint32_t u = ring.pop();
          state[u] = 2;
          if (u == t || gv[u] + hf(u) >= best) continue;
          for (int m = 0; m < 8; ++m) {
            const std::uint32_t v = u + static_cast<std::uint32_t>(mt.step[m]);
            if (g.cls[v] == kBlocked) continue;
            if (m >= 4 && (g.cls[u + static_cast<std::uint32_t>(mt.side_a[m])] == kBlocked ||
                           g.cls[u + static_cast<std::uint32_t>(mt.side_b[m])] == kBlocked))
              continue;
            const double ng = gv[u] + cost[m][g.cls[u]][g.cls[v]];
            if (state[v] != 0 && !(ng < gv[v] - 1e-9)) continue;
            if (state[v] == 1) ring.lower_key(v, gv[v] + hf(v), ng + hf(v));
            else ring.push(v, ng + hf(v));
            state[v] = 1;
            gv[v] = ng;
            if (v == t) best = std::min(best, ng);
          }
        }
        if (ref[t] == kInf) {
          EXPECT_EQ(best, kInf);
        } else {
          EXPECT_NEAR(best, ref[t], 1e-9 * ref[t]) << "u " << costs.unknown_cost << " goal " << tx << "," << ty;
        }
        ++checked;
      }
  }
  EXPECT_GT(checked, 300);
}

// GridSearch's engines on random grids with unknown cells at unknown_cost 2..50 against a plain
// Dijkstra: every cost equal.
TEST(GridSearchBuckets, ExactWithUnknownCostsAgainstDijkstra) {
  std::mt19937 rng(61);
  const int w = 48, h = 32;
  GridSearch search(w, h);
  int checked = 0;
  for (double u : {2.0, 3.5, 7.0, 13.0, 25.0, 50.0}) {
    for (int trial = 0; trial < 2; ++trial) {
      const PassGrid g = random_grid(rng, w, h, trial == 0 ? 0.1 : 0.3, 0.4);
      const CostModel costs{u};
      const std::vector<double> ref = dijkstra(g, g.index({0, 0}), costs);
      for (auto engine : {GridSearch::Engine::Auto, GridSearch::Engine::Buckets, GridSearch::Engine::Heap}) {
        search.set_engine(engine);
        for (int y = 0; y < h; y += 3)
          for (int x = 0; x < w; x += 4) {
            if (g.at({x, y}) == kBlocked) continue;
            const PlanResult r = search.find(g, {0, 0}, {x, y}, SearchMode::Optimal, costs);
            const double d = ref[g.index({x, y})];
            if (d == kInf) {
              EXPECT_EQ(r.status, PlanStatus::Unreachable);
            } else {
              ASSERT_TRUE(r.found());
              EXPECT_NEAR(r.cost, d, 1e-9 * d) << "engine " << static_cast<int>(engine) << " u " << u;
            }
            ++checked;
          }
      }
    }
  }
  EXPECT_GT(checked, 1000);
}

}  // namespace
}  // namespace robuter::plan
