// SPDX-License-Identifier: GPL-3.0-or-later
// The library's turn clearance (turning in place needs more room than driving) and prepare().
#include <gtest/gtest.h>

#include "modules/planner/lib/planner.hpp"

namespace robuter::plan {
namespace {

// A 6 x 6 m room split at y = 3 m by a wall with a 90 cm door (x from 2.5 to 3.4 m): each half
// is 2.9 m across, room enough to turn with a 25 cm clearance (a 2.24 m circle).
OccupancyMap door_map() {
  OccupancyMap map(MapGeometry{120, 120, 0.05, {0.0, 0.0}});
  for (int x = 0; x < 120; ++x) {
    map.mark_occupied({x, 0});
    map.mark_occupied({x, 119});
    const double cx = map.center({x, 60}).x;
    if (cx < 2.5 || cx > 3.4) map.mark_occupied({x, 60});
  }
  for (int y = 0; y < 120; ++y) {
    map.mark_occupied({0, y});
    map.mark_occupied({119, y});
  }
  return map;
}

PlannerConfig robuter(double turn_clearance) {
  PlannerConfig c;
  c.footprint = FootprintKind::Rectangle;
  c.rectangle.center_offset = 0.1825;
  c.turn_clearance = turn_clearance;
  return c;
}

TEST(TurnClearance, TurnsOnlyWhereTheGrownBodyFitsAndTheDoorStillPasses) {
  Planner p(robuter(0.25));
  p.set_map(door_map());
  const PlanResult r = p.plan({1.5, 1.5, 0.0}, {4.5, 4.5});
  ASSERT_TRUE(r.found()) << to_string(r.status);
  const auto& w = p.waypoints();
  int turns = 0;
  for (std::size_t i = 1; i < w.size(); ++i) {
    if (w[i].cell.x != w[i - 1].cell.x || w[i].cell.y != w[i - 1].cell.y) continue;
    ++turns;
    const Cell c{w[i].cell.x, w[i].cell.y};
    EXPECT_TRUE(p.can_turn(c, w[i].cell.slice));
    EXPECT_TRUE(p.can_turn(c, w[i - 1].cell.slice));
    EXPECT_GT(std::abs(w[i].pose.y - 3.025), 0.6) << "turned in the doorway";
  }
  EXPECT_GT(turns, 0);
  // Without the clearance the search may turn anywhere the body fits: never a longer path.
  Planner q(robuter(0.0));
  q.set_map(door_map());
  const PlanResult s = q.plan({1.5, 1.5, 0.0}, {4.5, 4.5});
  ASSERT_TRUE(s.found());
  EXPECT_LE(s.cost, r.cost + 1e-9);
}

TEST(TurnClearance, PrepareThenPlanEqualsPlan) {
  Planner a(robuter(0.25)), b(robuter(0.25));
  a.set_map(door_map());
  b.set_map(door_map());
  a.prepare({4.5, 4.5});
  const PlanResult ra = a.plan({1.5, 1.5, 0.3}, {4.5, 4.5});
  const PlanResult rb = b.plan({1.5, 1.5, 0.3}, {4.5, 4.5});
  ASSERT_TRUE(ra.found());
  EXPECT_DOUBLE_EQ(ra.cost, rb.cost);
  EXPECT_EQ(a.waypoints().size(), b.waypoints().size());
}

// Why: the module prepares a goal in steps (prepare_step, one per activation) while its sonar
// keeps writing the map: the steps must not fold those changes under the field (sync defers), and
// once the field is complete the next plan folds them, ending where a planner given the final map
// at once ends. A new goal in the middle starts the field again.
TEST(TurnClearance, PrepareInStepsDefersMapChangesAndEqualsAFreshPlan) {
  Planner a(robuter(0.25));
  a.set_map(door_map());
  ASSERT_FALSE(a.prepare_step({1.0, 4.5}, 500));  // another goal, dropped half-way
  int steps = 1;
  bool blocked_early = false;
  while (!a.prepare_step({4.5, 4.5}, 500)) {
    ++steps;
    if (steps == 3) {  // a new obstacle on the way to the door, mid-way
      for (int y = 15; y < 19; ++y)
        for (int x = 95; x < 99; ++x) a.map().mark_occupied({x, y});
      a.sync();  // deferred: the layers must not change under the field
      blocked_early = a.map().changes().empty() || a.expanded(0).at({96, 16}) == kBlocked;
    }
  }
  EXPECT_FALSE(blocked_early) << "a sync folded map changes while the field was being made";
  EXPECT_GT(steps, 3);
  const PlanResult ra = a.plan({1.5, 1.5, 0.3}, {4.5, 4.5});  // folds the change, repairs the field
  EXPECT_TRUE(a.map().changes().empty());
  EXPECT_EQ(a.expanded(0).at({96, 16}), kBlocked);
  OccupancyMap final_map = door_map();
  for (int y = 15; y < 19; ++y)
    for (int x = 95; x < 99; ++x) final_map.mark_occupied({x, y});
  Planner b(robuter(0.25));
  b.set_map(final_map);
  const PlanResult rb = b.plan({1.5, 1.5, 0.3}, {4.5, 4.5});
  ASSERT_EQ(ra.status, rb.status);
  ASSERT_TRUE(ra.found());
  EXPECT_DOUBLE_EQ(ra.cost, rb.cost);
  EXPECT_EQ(a.waypoints().size(), b.waypoints().size());
  EXPECT_EQ(a.expanded(0).cls, b.expanded(0).cls);
}

// Why: the module runs the search in steps too (plan_step, one per activation): the plan must
// equal plan()'s, map changes meanwhile wait for the next plan, another goal starts again, and
// cancel_steps() lets syncs through again.
TEST(TurnClearance, PlanInStepsEqualsPlanAndDefersMapChanges) {
  Planner a(robuter(0.25)), b(robuter(0.25));
  a.set_map(door_map());
  b.set_map(door_map());
  const Pose2 start{1.5, 1.5, 0.3};
  ASSERT_TRUE(a.prepare_step({4.5, 4.5}, 1u << 30));
  PlanResult ra;
  ASSERT_FALSE(a.plan_step(start, {1.0, 2.5}, 20, ra));  // another goal, dropped after one step
  int steps = 0;
  while (!a.plan_step(start, {4.5, 4.5}, 200, ra)) {
    ASSERT_TRUE(a.stepping());
    ASSERT_LT(++steps, 100000);
    if (steps == 2) {
      a.map().mark_occupied({96, 16});
      a.sync();  // deferred while the search runs
      EXPECT_FALSE(a.map().changes().empty());
    }
  }
  EXPECT_GT(steps, 2);
  EXPECT_FALSE(a.stepping());
  const PlanResult rb = b.plan(start, {4.5, 4.5});
  ASSERT_TRUE(ra.found());
  EXPECT_EQ(ra.cost, rb.cost);
  EXPECT_EQ(ra.expanded, rb.expanded);
  ASSERT_EQ(a.waypoints().size(), b.waypoints().size());
  for (std::size_t i = 0; i < a.waypoints().size(); ++i) EXPECT_EQ(a.waypoints()[i].cell, b.waypoints()[i].cell);
  // The deferred change is folded by the next sync; a search cut short lets syncs through.
  a.sync();
  EXPECT_TRUE(a.map().changes().empty());
  ASSERT_FALSE(a.plan_step(start, {4.5, 4.5}, 10, ra));
  a.map().mark_occupied({97, 16});
  a.cancel_steps();
  a.sync();
  EXPECT_TRUE(a.map().changes().empty());
  EXPECT_FALSE(a.stepping());
}

}  // namespace
}  // namespace robuter::plan
