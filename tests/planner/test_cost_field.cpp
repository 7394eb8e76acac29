// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the incremental cost field: equal to a full recomputation after random map changes.
#include <gtest/gtest.h>

#include <random>

#include "modules/planner/lib/cost_field.hpp"
#include "modules/planner/lib/grid_search.hpp"
#include "modules/planner/lib/planner.hpp"
#include "tests/support/sample.hpp"
#include "tests/planner/test_util.hpp"

namespace robuter::plan {
namespace {

// Why: the field must agree with A* from any start.
TEST(CostField, AgreesWithAStar) {
  std::mt19937 rng(3);
  const int w = 40, h = 30;
  PassGrid g(w, h);
  std::bernoulli_distribution blocked(0.25);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) g.set({x, y}, blocked(rng) ? kBlocked : kFree);
  const Cell goal{20, 15};
  g.set(goal, kFree);
  CostField f;
  ASSERT_TRUE(f.compute(g, goal));
  GridSearch s(w, h);
  std::vector<Cell> path;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (g.at({x, y}) == kBlocked) continue;
      const PlanResult a = s.find(g, {x, y}, goal, SearchMode::Optimal);
      const PlanResult b = f.path_from({x, y}, path);
      ASSERT_EQ(a.status, b.status) << x << "," << y;
      if (a.found()) {
        EXPECT_NEAR(a.length, b.length, 1e-9);
        EXPECT_NEAR(f.cost({x, y}), a.cost, 1e-9);
        EXPECT_EQ(path.front(), (Cell{x, y}));
        EXPECT_EQ(path.back(), goal);
      }
    }
}

// Why: the planner module computes a new goal's field in steps (one per activation); any step
// size must give exactly the field of one computation, and report completion only at the end.
TEST(CostField, InStepsEqualsOneComputation) {
  std::mt19937 rng(5);
  const int w = 60, h = 45;
  PassGrid g(w, h);
  std::uniform_int_distribution<int> cls(0, 9);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) g.set({x, y}, cls(rng) < 2 ? kBlocked : cls(rng) < 3 ? kUnknown : kFree);
  const Cell goal{30, 20};
  g.set(goal, kFree);
  CostModel costs;
  costs.unknown_cost = 3.0;
  CostField one;
  ASSERT_TRUE(one.compute(g, goal, costs));
  for (const std::uint32_t budget : {1u, 7u, 100u, 1000u, 100000u}) {
    CostField f;
    f.begin(g, goal, costs);
    int steps = 0;
    while (!f.step(budget)) {
      ASSERT_TRUE(f.pending());
      ASSERT_LT(++steps, w * h * 4) << "never completes with " << budget << " cells a step";
    }
    EXPECT_FALSE(f.pending());
    EXPECT_TRUE(f.step(budget));  // a completed field stays complete
    EXPECT_EQ(f.last_settled(), one.last_settled()) << budget;
    if (budget == 1u) {
      EXPECT_GT(steps, 1000);
    }
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) ASSERT_EQ(f.cost({x, y}), one.cost({x, y})) << x << "," << y << " budget " << budget;
  }
}

// Why: the incremental repair is the risky part; compare it with a fresh field after each of
// many random batches of changes (blocking, freeing, unknown with a cost, the goal itself).
TEST(CostField, IncrementalRepairEqualsRecomputation) {
  for (double unknown_cost : {1.0, 2.5}) {
    std::mt19937 rng(11);
    const int w = 36, h = 28;
    PassGrid g(w, h);
    std::uniform_int_distribution<int> cls(0, 9);
    auto random_class = [&] {
      const int c = cls(rng);
      return c < 3 ? kBlocked : c < 5 ? kUnknown : kFree;
    };
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) g.set({x, y}, random_class());
    const Cell goal{17, 13};
    g.set(goal, kFree);
    const CostModel costs{unknown_cost};
    CostField inc;
    inc.compute(g, goal, costs);
    std::uniform_int_distribution<int> cx(0, w - 1), cy(0, h - 1), batch(1, 12);
    for (int round = 0; round < 150; ++round) {
      std::vector<ClassChange> changes;
      const int n = batch(rng);
      for (int i = 0; i < n; ++i) {
        Cell c{cx(rng), cy(rng)};
        if (round % 37 == 5 && i == 0) c = goal;  // sometimes the goal itself
        const std::uint8_t before = g.at(c);
        const std::uint8_t after = random_class();
        if (before == after) continue;
        bool dup = false;
        for (const ClassChange& ch : changes) dup = dup || ch.index == g.index(c);
        if (dup) continue;
        g.set(c, after);
        changes.push_back({g.index(c), before});
      }
      inc.update(changes);
      CostField full;
      full.compute(g, goal, costs);
      std::vector<Cell> path;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const double a = inc.cost({x, y}), b = full.cost({x, y});
          if (b == CostField::kInfinity) {
            ASSERT_EQ(a, CostField::kInfinity) << "round " << round << " at " << x << "," << y;
          } else {
            ASSERT_NEAR(a, b, 1e-9) << "round " << round << " at " << x << "," << y;
            const PlanResult r = inc.path_from({x, y}, path);
            ASSERT_TRUE(r.found());
            ASSERT_NEAR(r.cost, b, 1e-9);
          }
        }
    }
  }
}

// Why: the planner facade replans toward the same goal after beams without a full search, and
// its answer equals a planner built from scratch on the updated map.
TEST(Planner, IncrementalReplanAfterBeams) {
  OccupancyMap map(MapGeometry{120, 80, 0.05, {}});
  PlannerConfig cfg;
  cfg.radius = 0.15;
  Planner inc(cfg);
  inc.set_map(map);
  const Pose2 start{0.5, 2.0, 0.0};
  const Point2 goal{5.5, 2.0};
  const PlanResult first = inc.plan(start, goal);
  ASSERT_TRUE(first.found());
  EXPECT_NEAR(first.length * 0.05, 5.0, 1e-9);
  const std::uint32_t full_effort = inc.field().last_settled();
  // A wall appears across the straight line: 10 readings of each beam make it an obstacle.
  for (int rep = 0; rep < 10; ++rep)
    for (int i = -20; i <= 20; ++i)
      inc.map().integrate_beam({1.0, 2.0 + i * 0.02}, 0.0, 2.0, 3.0);
  const PlanResult second = inc.plan(start, goal);
  ASSERT_TRUE(second.found());
  EXPECT_GT(second.length, first.length);
  EXPECT_LT(inc.field().last_settled(), full_effort);  // repaired, not recomputed
  cfg.incremental = false;
  Planner fresh(cfg);
  fresh.set_map(inc.map());
  const PlanResult ref = fresh.plan(start, goal);
  ASSERT_TRUE(ref.found());
  EXPECT_NEAR(second.cost, ref.cost, 1e-9);
  // Waypoints are cell centres in metres, start first.
  ASSERT_FALSE(inc.waypoints().empty());
  EXPECT_NEAR(inc.waypoints().front().pose.x, 0.525, 1e-9);
  EXPECT_NEAR(inc.waypoints().back().pose.x, 5.525, 1e-9);
}


// Why: a rectangle of 35 x 25 cm, 5 cm ahead of its axle, 8 slices over a half turn: small
// enough for quick facade tests on maps of a few metres.
PlannerConfig small_rectangle(double turn_clearance) {
  PlannerConfig cfg;
  cfg.footprint = FootprintKind::Rectangle;
  cfg.rectangle = RectangleFootprint{0.35, 0.25, 0.05, 0.0};
  cfg.heading_slices = 8;
  cfg.turn_clearance = turn_clearance;
  return cfg;
}

// Why: the rectangle's heuristic field is not repaired after syncs that only add obstacles (it
// stays admissible and consistent) and is dropped when a later sync makes a cell cheaper; either
// way every replan must cost what a planner built from scratch on the same map finds. Random
// blocks raised and cleared between plans, the start moving between them.
TEST(Planner, RectangleReplansAfterRaisesAndClearsEqualAFreshPlanner) {
  std::mt19937 rng(41204);
  const PlannerConfig cfg = small_rectangle(0.05);
  Planner inc(cfg);
  inc.set_map(test::free_map(80, 60));
  const Point2 goals[] = {{3.6, 2.6}, {3.6, 0.4}, {2.0, 2.7}};  // a new goal: a field made with the blocks
  int found = 0, deferred_then_cleared = 0;
  std::vector<Cell> raised;  // corners of the blocks raised so far
  const int rounds = ::robuter::test::sample(60, 15);
  for (int round = 0; round < rounds; ++round) {
    const bool clear = rng() % 3 == 0 && !raised.empty();
    int bx = static_cast<int>(rng() % 70), by = static_cast<int>(rng() % 50);
    if (clear) {  // an earlier block cleared: cells become cheaper
      const std::size_t i = rng() % raised.size();
      bx = raised[i].x;
      by = raised[i].y;
      raised.erase(raised.begin() + static_cast<std::ptrdiff_t>(i));
    } else {
      raised.push_back({bx, by});
    }
    for (int dy = 0; dy < 6; ++dy)
      for (int dx = 0; dx < 6; ++dx) {
        if (clear) inc.map().mark_free({bx + dx, by + dy});
        else inc.map().mark_occupied({bx + dx, by + dy});
      }
    deferred_then_cleared += clear;
    const Pose2 start{0.3 + 0.05 * static_cast<double>(rng() % 20), 0.3 + 0.05 * static_cast<double>(rng() % 40),
                      0.5 * static_cast<double>(rng() % 12)};
    const Point2 goal = goals[(round / 4) % 3];
    const PlanResult a = inc.plan(start, goal);
    Planner fresh(cfg);
    fresh.set_map(inc.map());
    const PlanResult b = fresh.plan(start, goal);
    SCOPED_TRACE(testing::Message() << "round " << round);
    ASSERT_EQ(a.status, b.status);
    if (a.found()) {
      ++found;
      ASSERT_NEAR(a.cost, b.cost, 1e-9);
    }
  }
  EXPECT_GT(found, rounds / 3);
  EXPECT_GT(deferred_then_cleared, 0);
}

// Why: the case the deferred field must not miss: a goal's field made while a wall stood between
// the robot and the goal (the wall's cells unreachable in it), a raise-only sync (the field kept
// as it was), then the wall cleared: the plan must take the way through, as a fresh planner does.
TEST(Planner, RectangleFieldIsRemadeWhenAWallClearsAfterADeferredRepair) {
  const PlannerConfig cfg = small_rectangle(0.0);
  OccupancyMap base = test::free_map(80, 60);
  for (int y = 0; y < 56; ++y) base.mark_occupied({40, y});  // a wall with a gap at the top
  Planner inc(cfg);
  inc.set_map(base);
  const Pose2 start{0.5, 0.5, 0.0};
  const Point2 goal{3.5, 0.5};
  const PlanResult around = inc.plan(start, goal);
  ASSERT_TRUE(around.found());
  inc.map().mark_occupied({10, 50});  // raise only: the field's repair waits
  ASSERT_TRUE(inc.plan(start, goal).found());
  for (int y = 0; y < 56; ++y) inc.map().mark_free({40, y});  // the wall goes
  const PlanResult through = inc.plan(start, goal);
  Planner fresh(cfg);
  fresh.set_map(inc.map());
  const PlanResult ref = fresh.plan(start, goal);
  ASSERT_TRUE(through.found());
  ASSERT_TRUE(ref.found());
  EXPECT_NEAR(through.cost, ref.cost, 1e-9);
  EXPECT_LT(through.cost, around.cost - 20.0);  // straight through, not round the wall's end
}

}  // namespace
}  // namespace robuter::plan
