// SPDX-License-Identifier: GPL-3.0-or-later
// Routes over places: Dijkstra through the doors, against every route enumerated on random graphs.
#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "modules/places/place_route.hpp"

namespace robuter::places {
namespace {

// A row of unit squares 0..n-1 along x, each joined to the next by a door on the shared edge.
PlaceGraph row(int n) {
  std::vector<Place> p;
  std::vector<Door> d;
  for (int i = 0; i < n; ++i) {
    const double x = 4.0 * i;
    p.push_back({"p" + std::to_string(i), {{x, 0}, {x + 4, 0}, {x + 4, 4}, {x, 4}}, {x + 2, 2}});
    if (i > 0) d.push_back({"d" + std::to_string(i), static_cast<std::size_t>(i - 1), static_cast<std::size_t>(i), {x, 2}, 0.9});
  }
  return PlaceGraph(std::move(p), std::move(d));
}

TEST(PlaceRoute, AlongARow) {
  const PlaceGraph g = row(5);
  const PlaceRoute r = shortest_route(g, 0, 4);
  ASSERT_TRUE(r.found);
  ASSERT_EQ(r.legs.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(r.legs[k].place, k + 1);
    EXPECT_EQ(r.legs[k].door, k);
  }
  EXPECT_DOUBLE_EQ(r.length, 16.0);
  const PlaceRoute back = shortest_route(g, 4, 0);
  ASSERT_TRUE(back.found);
  EXPECT_EQ(back.legs.back().place, 0u);
  EXPECT_DOUBLE_EQ(back.length, 16.0);
}

TEST(PlaceRoute, ToItselfIsFoundAndEmpty) {
  const PlaceRoute r = shortest_route(row(2), 1, 1);
  EXPECT_TRUE(r.found);
  EXPECT_TRUE(r.legs.empty());
  EXPECT_EQ(r.length, 0.0);
}

TEST(PlaceRoute, DisconnectedOrInvalidIsNotFound) {
  PlaceGraph g({Place{"a", {{0, 0}, {1, 0}, {1, 1}}, {0.6, 0.3}}, Place{"b", {{5, 0}, {6, 0}, {6, 1}}, {5.6, 0.3}}}, {});
  EXPECT_FALSE(shortest_route(g, 0, 1).found);
  EXPECT_FALSE(shortest_route(g, 0, 7).found);
}

// A leg is weighed through its door: a door far from the line between the centres makes the
// route that uses it longer than the centres' distance (seed 003's weight would not see it).
TEST(PlaceRoute, ALegGoesThroughItsDoor) {
  PlaceGraph g({Place{"a", {{0, 0}, {4, 0}, {4, 10}, {0, 10}}, {2, 1}},
                Place{"b", {{4, 0}, {8, 0}, {8, 10}, {4, 10}}, {6, 1}},
                Place{"c", {{0, 10}, {8, 10}, {8, 12}, {0, 12}}, {4, 11}}},
               {Door{"far", 0, 1, {4, 9}, 0.9}, Door{"ac", 0, 2, {2, 10}, 0.9}, Door{"cb", 2, 1, {6, 10}, 0.9}});
  const PlaceRoute r = shortest_route(g, 0, 1);
  ASSERT_TRUE(r.found);
  ASSERT_EQ(r.legs.size(), 1u) << "through 'far': 2 * hypot(2, 8) = 16.49 m; via c: 2 * 9.22 + 2 * 2.24 = 22.9 m";
  EXPECT_NEAR(r.length, 2 * std::hypot(2.0, 8.0), 1e-9);
}

// Property: on random grids of rooms with random doors, the route's length equals the
// shortest over every simple chain of doors (enumerated), and the legs chain up.
TEST(PlaceRoute, EqualsTheShortestOfEveryChainOnRandomGraphs) {
  std::mt19937 rng(17);
  for (int trial = 0; trial < 300; ++trial) {
    const int nx = 2 + static_cast<int>(rng() % 3), ny = 2 + static_cast<int>(rng() % 2);
    std::vector<Place> p;
    std::vector<Door> d;
    std::uniform_real_distribution<double> u(0.3, 3.7);
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x)
        p.push_back({"r" + std::to_string(y * nx + x), {{4.0 * x, 4.0 * y}, {4.0 * x + 4, 4.0 * y}, {4.0 * x + 4, 4.0 * y + 4}, {4.0 * x, 4.0 * y + 4}},
                     {4.0 * x + u(rng), 4.0 * y + u(rng)}});
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const auto i = static_cast<std::size_t>(y * nx + x);
        if (x + 1 < nx && rng() % 3 != 0) d.push_back({"e" + std::to_string(d.size()), i, i + 1, {4.0 * x + 4, 4.0 * y + u(rng)}, 0.9});
        if (y + 1 < ny && rng() % 3 != 0) d.push_back({"n" + std::to_string(d.size()), i, i + static_cast<std::size_t>(nx), {4.0 * x + u(rng), 4.0 * y + 4}, 0.9});
      }
    const PlaceGraph g(p, d);
    const std::size_t n = p.size(), from = rng() % n, to = rng() % n;
    double best = std::numeric_limits<double>::infinity();
    std::vector<bool> seen(n, false);
    std::function<void(std::size_t, double)> walk = [&](std::size_t v, double len) {
      if (v == to) { best = std::min(best, len); return; }
      seen[v] = true;
      for (const std::size_t k : g.doors_of(v)) {
        const Door& door = g.doors()[k];
        const std::size_t w = door.a == v ? door.b : door.a;
        if (!seen[w]) walk(w, len + (p[v].centre - door.at).norm() + (door.at - p[w].centre).norm());
      }
      seen[v] = false;
    };
    walk(from, 0.0);
    const PlaceRoute r = shortest_route(g, from, to);
    ASSERT_EQ(r.found, best < std::numeric_limits<double>::infinity()) << "trial " << trial;
    if (!r.found) continue;
    EXPECT_NEAR(r.length, best, 1e-9) << "trial " << trial;
    std::size_t at = from;
    double len = 0.0;
    for (const RouteLeg& leg : r.legs) {
      const Door& door = g.doors()[leg.door];
      ASSERT_TRUE((door.a == at && door.b == leg.place) || (door.b == at && door.a == leg.place)) << "trial " << trial;
      len += (p[at].centre - door.at).norm() + (door.at - p[leg.place].centre).norm();
      at = leg.place;
    }
    EXPECT_EQ(at, to);
    EXPECT_NEAR(len, r.length, 1e-9);
  }
}

}  // namespace
}  // namespace robuter::places
