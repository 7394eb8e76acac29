// SPDX-License-Identifier: GPL-3.0-or-later
// The route table: every pair's route as via points (before and after a narrow door, the middle of a wide one).
#include <gtest/gtest.h>

#include <array>

#include "modules/places/place_graph_file.hpp"
#include "modules/places/place_route.hpp"
#include "modules/places/route_table.hpp"

namespace robuter::places {
namespace {

// Three 4 m squares along x, a 0.9 m door between the first two, a 2 m one between the last two,
// and a fourth square apart (no door).
PlaceGraph three_and_one() {
  std::vector<Place> p;
  for (int i = 0; i < 3; ++i) {
    const double x = 4.0 * i;
    p.push_back({"p" + std::to_string(i), {{x, 0}, {x + 4, 0}, {x + 4, 4}, {x, 4}}, {x + 2, 2}});
  }
  p.push_back({"alone", {{20, 0}, {24, 0}, {24, 4}, {20, 4}}, {22, 2}});
  std::vector<Door> d{{"narrow", 0, 1, {4, 1}, 0.9}, {"wide", 1, 2, {8, 3}, 2.0}};
  return PlaceGraph(std::move(p), std::move(d));
}

TEST(RouteTable, NarrowDoorsTwoPointsWideDoorsOneThenTheCentre) {
  const PlaceGraph g = three_and_one();
  const RouteTable t(g);
  ASSERT_EQ(t.places(), 4u);
  ASSERT_TRUE(t.found(0, 2));
  const auto pts = t.points(0, 2);
  ASSERT_EQ(pts.size(), 4u);
  // 1.1 m before the narrow door facing it (its normal into p1: +x, heading 0), 0.9 m after it,
  // the wide door's middle, p2's centre.
  EXPECT_EQ(pts[0].x, 29000);
  EXPECT_EQ(pts[0].y, 10000);
  EXPECT_TRUE(pts[0].has_theta);
  EXPECT_EQ(pts[0].theta, 0);
  EXPECT_FALSE(pts[1].has_theta);
  EXPECT_EQ(pts[1].x, 49000);
  EXPECT_EQ(pts[1].y, 10000);
  EXPECT_EQ(pts[2].x, 80000);
  EXPECT_EQ(pts[2].y, 30000);
  EXPECT_EQ(pts[3].x, 100000);
  EXPECT_EQ(pts[3].y, 20000);
  EXPECT_EQ(t.doors(0, 2), 2u);
  EXPECT_DOUBLE_EQ(t.length(0, 2), shortest_route(g, 0, 2).length);
  // Backwards the narrow door's points swap sides: the normal points into p0 (-x).
  const auto back = t.points(2, 0);
  ASSERT_EQ(back.size(), 4u);
  EXPECT_EQ(back[1].x, 51000);
  EXPECT_EQ(back[1].theta, 18000) << "facing -x";
  EXPECT_EQ(back[2].x, 31000);
  // A place to itself: its centre alone; no door to "alone": not found.
  ASSERT_TRUE(t.found(1, 1));
  ASSERT_EQ(t.points(1, 1).size(), 1u);
  EXPECT_EQ(t.points(1, 1)[0].x, 60000);
  EXPECT_FALSE(t.found(0, 3));
  EXPECT_FALSE(t.found(3, 2));
  EXPECT_TRUE(t.points(0, 3).empty());
}

// Why: a hall 20 m long with a narrow door at each end: the way across it goes by its centre,
// so that no leg is longer than ViaRules::long_leg (the planner's window must hold each leg);
// a short room is crossed without it.
TEST(RouteTable, ALongWayAcrossAPlaceGoesByItsCentre) {
  std::vector<Place> p{{"west", {{-4, 0}, {0, 0}, {0, 4}, {-4, 4}}, {-2, 2}},
                       {"hall", {{0, 0}, {20, 0}, {20, 4}, {0, 4}}, {10, 2}},
                       {"east", {{20, 0}, {24, 0}, {24, 4}, {20, 4}}, {22, 2}}};
  std::vector<Door> d{{"w", 0, 1, {0, 2}, 0.9}, {"e", 1, 2, {20, 2}, 0.9}};
  const PlaceGraph g(std::move(p), std::move(d));
  const RouteTable t(g);
  const auto pts = t.points(0, 2);
  ASSERT_EQ(pts.size(), 6u) << "before, after, the hall's centre, before, after, the goal";
  EXPECT_EQ(pts[2].x, 100000);
  EXPECT_EQ(pts[2].y, 20000);
  EXPECT_FALSE(pts[2].has_theta);
  EXPECT_FALSE(pts[2].spin);
  const RouteTable short_hall(g, ViaRules{.long_leg = 20.0});
  EXPECT_EQ(short_hall.points(0, 2).size(), 5u) << "with a longer limit: straight across";
}

// Why: exploring (XQ <n> 1) visits each place's centre on the route with a full-turn scan: the
// start's, then after each door's points the entered place's, then the goal (the last centre
// again); the door points are the plain route's; a buffer too small gives 0, not a cut route.
TEST(RouteTable, ExploringAddsEachPlacesCentreToSpinAt) {
  const PlaceGraph g = three_and_one();
  const RouteTable t(g);
  std::array<ViaPoint, RouteTable::kMaxPoints> out{};
  const std::size_t n = t.explore_points(0, 2, out);
  ASSERT_EQ(n, 7u);
  const auto plain = t.points(0, 2);
  const auto is = [](const ViaPoint& p, std::int32_t x, std::int32_t y, bool spin) {
    return p.x == x && p.y == y && p.spin == spin;
  };
  EXPECT_TRUE(is(out[0], 20000, 20000, true)) << "p0's centre";
  EXPECT_TRUE(is(out[1], plain[0].x, plain[0].y, false));
  EXPECT_TRUE(out[1].has_theta) << "the point before the narrow door still faces it";
  EXPECT_TRUE(is(out[2], plain[1].x, plain[1].y, false));
  EXPECT_TRUE(is(out[3], 60000, 20000, true)) << "p1's centre";
  EXPECT_TRUE(is(out[4], plain[2].x, plain[2].y, false)) << "the wide door's middle";
  EXPECT_TRUE(is(out[5], 100000, 20000, true)) << "p2's centre, to scan";
  EXPECT_TRUE(is(out[6], 100000, 20000, false)) << "and as the goal";
  for (const ViaPoint& p : plain) EXPECT_FALSE(p.spin) << "the plain route does not spin";
  EXPECT_EQ(t.explore_points(1, 1, out), 2u) << "its own place: the centre to spin at, then the goal";
  EXPECT_TRUE(out[0].spin);
  EXPECT_EQ(t.explore_points(0, 3, out), 0u) << "no route";
  std::array<ViaPoint, 6> small{};
  EXPECT_EQ(t.explore_points(0, 2, small), 0u) << "more points than the buffer";
}

// Why: on the shipped floor every pair is joined, within the planner goal's 64 points, and
// every via point lies inside a place of the route (never in a wall).
TEST(RouteTable, EveryPairOfTheBuildingFloor) {
  auto loaded = load_place_graph(ROBUTER_SHIPPED_WORLDS "/building_floor.places.toml");
  ASSERT_TRUE(loaded.ok());
  const PlaceGraph& g = loaded.value();
  const RouteTable t(g);
  for (std::size_t a = 0; a < g.places().size(); ++a)
    for (std::size_t b = 0; b < g.places().size(); ++b) {
      ASSERT_TRUE(t.found(a, b)) << g.places()[a].name << " -> " << g.places()[b].name;
      ASSERT_LE(t.points(a, b).size(), RouteTable::kMaxPoints);
      std::array<ViaPoint, RouteTable::kMaxPoints> explore{};
      EXPECT_GT(t.explore_points(a, b, explore), t.points(a, b).size()) << "every exploration fits a goal";
      for (const ViaPoint& p : t.points(a, b))
        EXPECT_TRUE(g.place_at({p.x * 1e-4, p.y * 1e-4}).has_value())
            << g.places()[a].name << " -> " << g.places()[b].name << ": (" << p.x << ", " << p.y << ")";
      // Every leg, from the start place's centre on, fits the planner's window (16 m: 14.3 m along
      // each axis with its margins; ViaRules::long_leg, 12.5 m, keeps them shorter).
      Vec2 from = g.places()[a].centre;
      for (const ViaPoint& p : t.points(a, b)) {
        const Vec2 to(p.x * 1e-4, p.y * 1e-4);
        EXPECT_LE((to - from).norm(), 12.5) << g.places()[a].name << " -> " << g.places()[b].name;
        from = to;
      }
    }
}

}  // namespace
}  // namespace robuter::places
