// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the occupancy grid: beam integration (seed 003's rule), change log, text rendering.
#include <gtest/gtest.h>

#include <cmath>

#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/planner/lib/text_render.hpp"

namespace robuter::plan {
namespace {

OccupancyMap small_map() { return OccupancyMap(MapGeometry{20, 10, 0.1, {0.0, 0.0}}); }

TEST(OccupancyMap, NeverSeenIsUnknown) {
  const OccupancyMap m = small_map();
  EXPECT_EQ(m.state({3, 3}), CellState::Unknown);
  EXPECT_EQ(m.count({3, 3}), OccupancyMap::kUnknown);
}

TEST(OccupancyMap, HitsReachThresholdThenObstacle) {
  OccupancyMap m = small_map();
  // From (0.05, 0.55) along +x, 1.0 m: hit cell is x = 10, row 5.
  for (int i = 0; i < 9; ++i) m.integrate_beam({0.05, 0.55}, 0.0, 1.0, 1.5);
  EXPECT_EQ(m.count({10, 5}), 9);
  EXPECT_EQ(m.state({10, 5}), CellState::Free);
  m.integrate_beam({0.05, 0.55}, 0.0, 1.0, 1.5);
  EXPECT_EQ(m.state({10, 5}), CellState::Occupied);
  for (int x = 0; x < 10; ++x) EXPECT_EQ(m.count({x, 5}), 0) << x;  // seen, free
  EXPECT_EQ(m.state({11, 5}), CellState::Unknown);                    // beyond the hit
}

TEST(OccupancyMap, MissesTakeOneDownToZero) {
  OccupancyMap m = small_map();
  for (int i = 0; i < 12; ++i) m.integrate_beam({0.05, 0.55}, 0.0, 1.0, 1.5);
  ASSERT_EQ(m.count({10, 5}), 12);
  // Longer readings along the same row now pass through cell 10: each takes 1 off.
  for (int i = 0; i < 3; ++i) m.integrate_beam({0.05, 0.55}, 0.0, 1.6, 1.5);
  EXPECT_EQ(m.count({10, 5}), 9);
  EXPECT_EQ(m.state({10, 5}), CellState::Free);
  EXPECT_EQ(m.count({15, 5}), 0);  // max range: no hit at the end
}

TEST(OccupancyMap, SeedThreesInitialCountFiveAndThresholdTen) {
  OccupancyMap m(MapGeometry{20, 10, 0.1, {0.0, 0.0}}, 10, 5);
  EXPECT_EQ(m.initial_count(), 5);
  EXPECT_EQ(m.state({10, 5}), CellState::Unknown);  // never seen: still unknown until a beam
  for (int i = 0; i < 4; ++i) m.integrate_beam({0.05, 0.55}, 0.0, 1.0, 1.5);
  EXPECT_EQ(m.count({10, 5}), 9);                     // 5 + 4 hits
  EXPECT_EQ(m.state({10, 5}), CellState::Free);
  m.integrate_beam({0.05, 0.55}, 0.0, 1.0, 1.5);
  EXPECT_EQ(m.state({10, 5}), CellState::Occupied);   // 5 hits from unknown (seed 003: >= 10)
  EXPECT_EQ(m.count({9, 5}), 0);                      // 5 misses: 5 -> 0
  m.integrate_beam({0.05, 0.75}, 0.0, 1.0, 1.5);
  EXPECT_EQ(m.count({5, 7}), 4);                      // one miss from unknown: 4, free
}

TEST(OccupancyMap, BeamLeavingTheMapIsClipped) {
  OccupancyMap m = small_map();
  m.integrate_beam({1.0, 0.55}, kPi / 2, 50.0, 100.0);
  for (int y = 5; y < 10; ++y) EXPECT_EQ(m.state({10, y}), CellState::Free);
  m.integrate_beam({1.0, 0.55}, 0.0, 1e12, 1e13);  // huge ranges are harmless
  EXPECT_EQ(m.state({19, 5}), CellState::Free);
  m.integrate_beam({-1e12, 0.75}, 0.0, 2e12, 3e12);  // far origin: only the map part is walked
  EXPECT_EQ(m.state({0, 7}), CellState::Free);
  m.integrate_beam({std::nan(""), 0.0}, 0.0, 1.0, 2.0);  // ignored
}

TEST(OccupancyMap, ChangeLogListsStateChangesOnce) {
  OccupancyMap m = small_map();
  m.mark_occupied({1, 1});
  m.mark_occupied({1, 1});
  m.mark_free({2, 2});
  m.set_count({3, 3}, 0);
  m.set_count({3, 3}, 1);  // free -> free: counted once
  ASSERT_EQ(m.changes().size(), 3u);
  m.clear_changes();
  EXPECT_TRUE(m.changes().empty());
  m.mark_free({1, 1});
  EXPECT_EQ(m.changes().size(), 1u);
}

TEST(OccupancyMap, WorldCellConversion) {
  const OccupancyMap m(MapGeometry{10, 10, 0.05, {-1.0, 2.0}});
  EXPECT_EQ(m.cell_of({-1.0, 2.0}), (Cell{0, 0}));
  EXPECT_EQ(m.cell_of({-0.951, 2.049}), (Cell{0, 0}));
  EXPECT_EQ(m.cell_of({-0.949, 2.051}), (Cell{1, 1}));
  EXPECT_FALSE(m.contains(m.cell_of({-1.01, 2.0})));
  EXPECT_NEAR(m.center({1, 1}).x, -0.925, 1e-12);
  EXPECT_FALSE(m.contains(m.cell_of({1e300, -1e300})));
  EXPECT_FALSE(m.contains(m.cell_of({std::nan(""), 0.0})));
}

TEST(TextRender, SeedCharacters) {
  OccupancyMap m(MapGeometry{4, 3, 0.05, {}});
  m.mark_free({0, 0});
  m.mark_free({1, 0});
  m.mark_occupied({2, 0});
  m.mark_free({0, 2});
  const std::string s = render_text(m, 0, 0, 5, 3, Cell{1, 0});
  EXPECT_EQ(s, " ....\n.....\n P#..\n");  // top row first; x = 4 is outside: '.'
  const std::string around = render_around(m, {1, 1}, 1);
  EXPECT_EQ(around, " ..\n.P.\n  #\n");
}

// Why (issue #22): seed 000's gt.log marks: O the start (M on an obstacle), D the goal, X blocked.
TEST(TextRender, TheThesisLogMarksStartGoalAndObstacles) {
  PassGrid g(4, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) g.set({x, y}, kFree);
  g.set({2, 0}, kBlocked);
  g.set({2, 1}, kBlocked);
  EXPECT_EQ(render_thesis_log(g, {0, 0}, {3, 1}), "  XD\nO X \n");
  EXPECT_EQ(render_thesis_log(g, {2, 0}, {3, 1}), "  XD\n  M \n");
}

}  // namespace
}  // namespace robuter::plan
