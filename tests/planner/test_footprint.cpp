// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of footprints and the (x, y, heading) search: the Robuter passes a 90 cm door, a disc does not.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "modules/planner/lib/cost_field.hpp"
#include "modules/planner/lib/cspace.hpp"

#include "modules/planner/lib/footprint.hpp"
#include "modules/planner/lib/heading_search.hpp"
#include "modules/planner/lib/planner.hpp"
#include "modules/planner/lib/thesis_files.hpp"

namespace robuter::plan {
namespace {

TEST(Footprint, DiscMask) {
  const FootprintMask m = disc_mask(0.30, 0.05);  // 6 cells
  EXPECT_TRUE(m.contains(0, 0));
  EXPECT_TRUE(m.contains(6, 0));    // square starts 5.5 cells away
  EXPECT_FALSE(m.contains(7, 0));   // 6.5 away
  EXPECT_TRUE(m.contains(4, 4));    // corner 3.5, 3.5: 4.95 away
  EXPECT_FALSE(m.contains(5, 5));   // corner 4.5, 4.5: 6.36 away
  const FootprintMask point = disc_mask(0.0, 0.05);
  EXPECT_EQ(point.cells(), 1);
}

TEST(Footprint, RectangleMaskFollowsHeading) {
  const RectangleFootprint robuter;
  // At heading 0 (exactly): half length 10.25 cells, half width 7 cells.
  const FootprintMask m0 = rectangle_mask(robuter, 0.05, 0.0, 0.0);
  EXPECT_TRUE(m0.contains(10, 0));
  EXPECT_FALSE(m0.contains(11, 0));
  EXPECT_TRUE(m0.contains(0, 7));
  EXPECT_FALSE(m0.contains(0, 8));
  const FootprintMask m90 = rectangle_mask(robuter, 0.05, kPi / 2, kPi / 2);
  EXPECT_TRUE(m90.contains(0, 10));
  EXPECT_FALSE(m90.contains(0, 11));
  EXPECT_FALSE(m90.contains(8, 0));
  // A swept slice holds both ends of its interval.
  const FootprintMask swept = rectangle_mask(robuter, 0.05, -0.2, 0.2);
  const FootprintMask lo = rectangle_mask(robuter, 0.05, -0.2, -0.2);
  for (const MaskRun& r : lo.runs)
    for (int dx = r.lo; dx <= r.hi; ++dx) EXPECT_TRUE(swept.contains(dx, r.dy));
  EXPECT_NEAR(circumscribed_radius(robuter), 0.6206, 1e-3);
  EXPECT_NEAR(inscribed_radius(robuter), 0.35, 1e-12);
}

// Why: the prefix-sum build and the incremental stamping must both equal brute force.
TEST(CSpaceLayer, BuildAndUpdateEqualBruteForce) {
  std::mt19937 rng(4);
  OccupancyMap map(MapGeometry{37, 23, 0.05, {}});
  std::uniform_int_distribution<int> pick(0, 19);
  for (int y = 0; y < 23; ++y)
    for (int x = 0; x < 37; ++x) {
      const int v = pick(rng);
      if (v == 0) map.mark_occupied({x, y});
      else if (v < 12) map.mark_free({x, y});
    }
  map.clear_changes();
  const FootprintMask mask = rectangle_mask(RectangleFootprint{}, 0.1, 0.3, 0.5);
  CSpaceStack stack;
  stack.reset(map);
  CSpaceLayer layer;
  layer.build(map, mask);
  auto expect_brute = [&](const char* when) {
    for (int y = 0; y < 23; ++y)
      for (int x = 0; x < 37; ++x) {
        bool hit = false;
        for (const MaskRun& r : mask.runs)
          for (int dx = r.lo; dx <= r.hi; ++dx) {
            const Cell o{x + dx, y + r.dy};
            hit = hit || (map.contains(o) && map.state(o) == CellState::Occupied);
          }
        const std::uint8_t want = hit ? kBlocked : map.state({x, y}) == CellState::Unknown ? kUnknown : kFree;
        ASSERT_EQ(layer.grid().at({x, y}), want) << when << " at " << x << "," << y;
      }
  };
  expect_brute("build");
  std::vector<ClassChange> changes;
  std::uniform_int_distribution<int> cx(0, 36), cy(0, 22);
  for (int round = 0; round < 30; ++round) {
    for (int k = 0; k < 4; ++k) {
      const Cell c{cx(rng), cy(rng)};
      const int v = pick(rng);
      if (v < 7) map.mark_occupied(c);
      else if (v < 14) map.mark_free(c);
      else map.set_count(c, OccupancyMap::kUnknown);
    }
    changes.clear();
    stack.begin_sync(map, map.changes());
    layer.update(stack, map, map.changes(), &changes);
    stack.end_sync(map.changes());
    map.clear_changes();
    expect_brute("update");
    for (const ClassChange& ch : changes) EXPECT_NE(layer.grid().cls[ch.index], ch.before);
  }
}

TEST(Footprint, SlicesCoverTheFullTurn) {
  EXPECT_EQ(slice_of_heading(0.0, 32), 0);
  EXPECT_EQ(slice_of_heading(kPi, 32), 16);          // the body is not symmetric: pi is its own slice
  EXPECT_EQ(slice_of_heading(kPi / 2, 32), 8);
  EXPECT_EQ(slice_of_heading(-kPi / 2, 32), 24);
  EXPECT_EQ(slice_of_heading(kPi - 0.01, 32), 16);
  EXPECT_EQ(slice_of_heading(2 * kPi - 0.01, 32), 0);
  EXPECT_EQ(allowed_moves(0, 32, MotionModel::Aligned), (1u << 1) | (1u << 3));  // +-x
  EXPECT_EQ(allowed_moves(4, 32, MotionModel::Aligned), (1u << 4) | (1u << 6));  // diagonal
  EXPECT_EQ(allowed_moves(8, 32, MotionModel::Aligned), (1u << 0) | (1u << 2));  // +-y
  EXPECT_EQ(allowed_moves(16, 32, MotionModel::Aligned), (1u << 1) | (1u << 3)); // +-x, facing west
  EXPECT_EQ(allowed_moves(3, 32, MotionModel::Aligned), 0u);
  EXPECT_EQ(allowed_moves(3, 32, MotionModel::Holonomic), 0xFFu);
}

// A 6 m x 4 m room split at y = 2 m by a wall with a 90 cm door (x from 2.5 to 3.4 m).
OccupancyMap door_map() {
  OccupancyMap m(MapGeometry{120, 80, 0.05, {}});
  for (int y = 0; y < 80; ++y)
    for (int x = 0; x < 120; ++x) m.mark_free({x, y});
  rasterise_polygons(m, {Polygon{{{0.0, 2.0}, {2.5, 2.0}, {2.5, 2.1}, {0.0, 2.1}}},
                         Polygon{{{3.45, 2.0}, {6.0, 2.0}, {6.0, 2.1}, {3.45, 2.1}}}});
  m.clear_changes();
  return m;
}

TEST(DoorCrossing, RectanglePassesDiscDoesNot) {
  const OccupancyMap map = door_map();
  const Pose2 start{1.0, 0.8, 0.0};
  const Point2 goal{5.0, 3.2};

  PlannerConfig disc;
  disc.radius = circumscribed_radius(RectangleFootprint{});
  Planner disc_planner(disc);
  disc_planner.set_map(map);
  EXPECT_EQ(disc_planner.plan(start, goal).status, PlanStatus::Unreachable);

  for (MotionModel motion : {MotionModel::Aligned, MotionModel::Holonomic}) {
    PlannerConfig rect;
    rect.footprint = FootprintKind::Rectangle;
    rect.motion = motion;
    Planner planner(rect);
    planner.set_map(map);
    const PlanResult r = planner.plan(start, goal);
    ASSERT_TRUE(r.found()) << to_string(r.status);
    const auto& wps = planner.waypoints();
    // Through the door: the path crosses y = 2.05 m between x = 2.5 and 3.45 m, heading
    // across the wall (slice 8 = 90 degrees).
    bool crossed = false;
    for (const Waypoint& w : wps)
      if (std::abs(w.pose.y - 2.075) < 0.03) {
        crossed = true;
        EXPECT_GT(w.pose.x, 2.5);
        EXPECT_LT(w.pose.x, 3.45);
        if (motion == MotionModel::Aligned) {
          EXPECT_TRUE(w.cell.slice == 8 || w.cell.slice == 24) << w.cell.slice;
        }
      }
    EXPECT_TRUE(crossed);
    // Aligned: every translation is along the current slice's heading.
    if (motion == MotionModel::Aligned)
      for (std::size_t i = 0; i + 1 < wps.size(); ++i) {
        const CellPose a = wps[i].cell, b = wps[i + 1].cell;
        if (a.x == b.x && a.y == b.y) continue;  // a turn
        ASSERT_EQ(a.slice, b.slice);
        int m = 0;
        while (kMoveDx[m] != b.x - a.x || kMoveDy[m] != b.y - a.y) ++m;
        EXPECT_TRUE(allowed_moves(a.slice, 32, MotionModel::Aligned) & (1u << m));
      }
  }
}

TEST(DoorCrossing, NarrowerDoorBlocksTheRectangleToo) {
  OccupancyMap m(MapGeometry{120, 80, 0.05, {}});
  rasterise_polygons(m, {Polygon{{{0.0, 2.0}, {2.5, 2.0}, {2.5, 2.1}, {0.0, 2.1}}},
                         Polygon{{{3.2, 2.0}, {6.0, 2.0}, {6.0, 2.1}, {3.2, 2.1}}}});
  PlannerConfig rect;
  rect.footprint = FootprintKind::Rectangle;
  Planner planner(rect);
  planner.set_map(m);
  EXPECT_EQ(planner.plan({1.0, 0.8, 0.0}, {5.0, 3.2}).status, PlanStatus::Unreachable);
}

// Why: the bucket-ring open list must give the heap's (exact) costs, with and without a
// heuristic field, in both motion models.
TEST(HeadingSearch, RingEqualsHeap) {
  std::mt19937 rng(8);
  const int w = 30, h = 24, k_count = 8;
  std::vector<PassGrid> grids(k_count, PassGrid(w, h));
  PassGrid relax(w, h);
  std::bernoulli_distribution blocked(0.12);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      bool any_free = false;
      for (int k = 0; k < k_count; ++k) {
        const bool b = blocked(rng);
        grids[static_cast<std::size_t>(k)].set({x, y}, b ? kBlocked : kFree);
        any_free = any_free || !b;
      }
      relax.set({x, y}, any_free ? kFree : kBlocked);
    }
  std::vector<const PassGrid*> slices;
  for (const PassGrid& g : grids) slices.push_back(&g);
  HeadingSearch search;
  std::uniform_int_distribution<int> px(0, w - 1), py(0, h - 1), pk(0, k_count - 1);
  int found = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const CellPose start{px(rng), py(rng), pk(rng)};
    const Cell goal{px(rng), py(rng)};
    CostField field;
    field.compute(relax, goal);
    for (MotionModel motion : {MotionModel::Aligned, MotionModel::Holonomic})
      for (const CostField* heuristic : {static_cast<const CostField*>(nullptr), static_cast<const CostField*>(&field)}) {
        HeadingOptions opt;
        opt.motion = motion;
        opt.rotation_step_cost = 0.7;
        const PlanResult a = search.find(slices, start, goal, opt, {}, heuristic);
        opt.heap = true;
        const PlanResult b = search.find(slices, start, goal, opt, {}, heuristic);
        ASSERT_EQ(a.status, b.status) << trial;
        if (a.found()) {
          ++found;
          EXPECT_NEAR(a.cost, b.cost, 1e-9) << trial;
        }
      }
  }
  EXPECT_GT(found, 40);
}

TEST(HeadingSearch, GoalOutsideAndBlockedStart) {
  OccupancyMap m(MapGeometry{60, 60, 0.05, {}});
  m.mark_occupied({30, 30});
  PlannerConfig rect;
  rect.footprint = FootprintKind::Rectangle;
  Planner planner(rect);
  planner.set_map(m);
  EXPECT_EQ(planner.plan({1.5, 1.5, 0.0}, {10.0, 1.0}).status, PlanStatus::GoalOutside);
  EXPECT_EQ(planner.plan({1.52, 1.52, 0.0}, {0.6, 0.6}).status, PlanStatus::StartBlocked);
}

// Why: the row-bitset build (span table, shifted word ORs) must equal brute force on maps
// several words wide, for runs wider than one 64-cell piece and offsets past a word either side
// of the robot's cell, for class layers and bit layers alike.
TEST(CSpaceLayer, WideMasksOnWideMapsEqualBruteForce) {
  std::mt19937 rng(11);
  for (int round = 0; round < 6; ++round) {
    const int w = 70 + 37 * round, h = 9 + 3 * round;
    OccupancyMap map(MapGeometry{w, h, 0.05, {}});
    std::uniform_int_distribution<int> pick(0, 59);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int v = pick(rng);
        if (v == 0) map.mark_occupied({x, y});
        else if (v < 30) map.mark_free({x, y});
      }
    map.clear_changes();
    // Runs of 1..200 cells at offsets from -150 to +150, a row or two each.
    FootprintMask mask;
    std::uniform_int_distribution<int> lo(-150, 100), len(0, 199), dy(-3, 3);
    for (int k = 0; k < 7; ++k) {
      const int a = lo(rng);
      mask.runs.push_back({dy(rng), a, a + len(rng)});
    }
    std::sort(mask.runs.begin(), mask.runs.end(),
              [](const MaskRun& a, const MaskRun& b) { return a.dy != b.dy ? a.dy < b.dy : a.lo < b.lo; });
    CSpaceLayer layer;
    layer.build(map, mask);
    SliceBits bits;
    bits.resize(w, h, 3);
    CSpaceLayer bit_layer;
    bit_layer.build_bits(map, mask, bits, 2);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        bool hit = map.state({x, y}) == CellState::Occupied;
        for (const MaskRun& r : mask.runs)
          for (int dx = r.lo; dx <= r.hi && !hit; ++dx) {
            const Cell o{x + dx, y + r.dy};
            hit = map.contains(o) && map.state(o) == CellState::Occupied;
          }
        const std::uint8_t want = hit ? kBlocked : map.state({x, y}) == CellState::Unknown ? kUnknown : kFree;
        ASSERT_EQ(layer.grid().at({x, y}), want) << "round " << round << " at " << x << "," << y;
        ASSERT_EQ(bits.blocked({x, y}, 2), hit) << "round " << round << " at " << x << "," << y;
        ASSERT_TRUE(bits.blocked({x, y}, 0) && bits.blocked({x, y}, 1));  // other slices untouched
      }
  }
}

}  // namespace
}  // namespace robuter::plan
