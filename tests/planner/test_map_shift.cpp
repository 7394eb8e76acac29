// SPDX-License-Identifier: GPL-3.0-or-later
// The map window's move: counts keep their world place, and the layers rebuilt step by step equal a fresh planner's.
#include <gtest/gtest.h>

#include <random>

#include "modules/planner/lib/planner.hpp"

namespace robuter::plan {
namespace {

// Why: a move by (dx, dy) cells keeps each count at its world position; what comes into view is
// unknown; the change log is empty (the layers are rebuilt, not updated).
TEST(MapShift, CountsKeepTheirWorldPlaceAndNewCellsAreUnknown) {
  for (const auto& [dx, dy] : {std::pair{3, -2}, std::pair{-5, 4}, std::pair{0, 7}, std::pair{-1, 0}}) {
    OccupancyMap m(MapGeometry{20, 15, 0.05, {-0.5, -0.25}}, 2);
    std::mt19937 rng(static_cast<unsigned>(dx * 31 + dy));
    for (int y = 0; y < 15; ++y)
      for (int x = 0; x < 20; ++x)
        if (rng() % 3 != 0) m.set_count({x, y}, static_cast<std::uint8_t>(rng() % 5));
    const OccupancyMap before = m;
    m.shift(dx, dy);
    EXPECT_TRUE(m.changes().empty());
    EXPECT_DOUBLE_EQ(m.geometry().origin.x, -0.5 + dx * 0.05);
    EXPECT_DOUBLE_EQ(m.geometry().origin.y, -0.25 + dy * 0.05);
    for (int y = 0; y < 15; ++y)
      for (int x = 0; x < 20; ++x) {
        const Cell old{x + dx, y + dy};
        const std::uint8_t want = before.contains(old) ? before.count(old) : OccupancyMap::kUnknown;
        ASSERT_EQ(m.count({x, y}), want) << dx << "," << dy << " cell " << x << "," << y;
        // the same world point names the same count
        if (before.contains(old)) {
          ASSERT_EQ(before.cell_of(m.center({x, y})), old);
        }
      }
  }
}

// Why: the facade's move: after shift_map and the stepwise rebuild, every body and turn layer,
// and the plan (whose heuristic is the relaxation layer), equal those of a planner given the
// moved map at once; rebuild_step reports done only at the end.
TEST(MapShift, LayersRebuiltStepByStepEqualAFreshPlanner) {
  PlannerConfig cfg;
  cfg.footprint = FootprintKind::Rectangle;
  cfg.rectangle = RectangleFootprint{1.025, 0.700, 0.183, 0.0};
  cfg.turn_clearance = 0.25;
  Planner p(cfg);
  OccupancyMap start(MapGeometry{80, 60, 0.05, {}}, 2);
  std::mt19937 rng(5);
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 80; ++x) {
      if ((x / 9 + y / 7) % 3 != 0) start.mark_free({x, y});
      if (rng() % 40 == 0) start.mark_occupied({x, y});
    }
  start.clear_changes();
  p.set_map(start);
  EXPECT_FALSE(p.rebuilding());
  p.shift_map(13, -9);
  EXPECT_TRUE(p.rebuilding());
  const int total = 2 * p.slices() + 1;  // body slices, turn slices, the relaxation
  int steps = 0;
  while (!p.rebuild_step(8)) ++steps;
  EXPECT_EQ(steps + 1, (total + 7) / 8);
  EXPECT_FALSE(p.rebuilding());
  Planner fresh(cfg);
  fresh.set_map(p.map());
  for (int k = 0; k < p.slices(); ++k) {
    ASSERT_EQ(p.expanded(k).cls, fresh.expanded(k).cls) << "slice " << k;
  }
  ASSERT_EQ(p.turn_room().bits, fresh.turn_room().bits) << "the turn layers (bits) after the move";
  const Pose2 from{p.map().center({20, 20}).x, p.map().center({20, 20}).y, 0.0};
  const Point2 to = p.map().center({60, 40});
  const PlanResult a = p.plan(from, to), b = fresh.plan(from, to);
  EXPECT_EQ(a.status, b.status);
  EXPECT_DOUBLE_EQ(a.cost, b.cost);
  EXPECT_EQ(a.expanded, b.expanded);
}

// Why: after a move the window takes the structure (walls at the most hits), then the memory of
// an earlier run (its obstacles at the threshold, its free cells free), each only where the map
// and those before it leave the cell unknown; a remembered obstacle clears with one miss, a wall
// does not.
TEST(MapShift, TheWindowTakesTheStructureThenTheMemoryWhereItKnowsNothing) {
  const MapGeometry floor{40, 10, 0.05, {-1.0, -0.25}};  // the floor: a strip of 2 m x 0.5 m
  OccupancyMap walls(floor, 2), memory(floor, 2);
  walls.mark_occupied({25, 5});
  memory.mark_occupied({25, 5});  // the wall again: the structure's stays
  memory.mark_occupied({26, 5});  // a remembered obstacle
  memory.mark_free({27, 5});      // remembered free
  memory.mark_free({28, 5});
  PlannerConfig cfg;
  Planner p(cfg);
  p.set_structure(&walls);
  p.set_memory(&memory);
  OccupancyMap window(MapGeometry{20, 10, 0.05, {-1.0, -0.25}}, 2);  // the floor's cells 0..19 at first
  p.set_map(window);
  EXPECT_EQ(p.map().state({19, 5}), CellState::Unknown);
  p.shift_map(10, 0);  // now the floor's cells 10..29
  while (!p.rebuild_step(100)) {}
  const OccupancyMap& m = p.map();
  EXPECT_EQ(m.count({15, 5}), OccupancyMap::kMaxCount) << "the wall: the most hits";
  EXPECT_EQ(m.count({16, 5}), m.threshold()) << "the remembered obstacle: the threshold";
  EXPECT_EQ(m.state({17, 5}), CellState::Free);
  EXPECT_EQ(m.state({18, 5}), CellState::Free);
  EXPECT_EQ(m.state({19, 5}), CellState::Unknown) << "neither knows it";
  // The memory fills only unknown cells: a window that saw (28, 5) occupied keeps it.
  Planner q(cfg);
  q.set_memory(&memory);
  OccupancyMap seen(MapGeometry{20, 10, 0.05, {-0.5, -0.25}}, 2);  // floor cells 10..29
  seen.mark_occupied({18, 5});
  q.set_map(seen);
  EXPECT_EQ(q.map().state({18, 5}), CellState::Occupied) << "what the run saw stays";
  EXPECT_EQ(q.map().state({17, 5}), CellState::Free) << "set_map takes the memory too";
}

}  // namespace
}  // namespace robuter::plan
