// SPDX-License-Identifier: GPL-3.0-or-later
// The shipped building floor (worlds/building_floor.*) read by the firmware's loaders, and its
// place graph checked against the world it was drawn for.
#include <gtest/gtest.h>

#include <limits>

#include "hal/sim/geometry.hpp"
#include "hal/sim/world_io.hpp"
#include "modules/places/place_graph_file.hpp"
#include "modules/places/place_route.hpp"

namespace robuter::places {
namespace {

struct Floor {
  sim::World world;
  PlaceGraph graph;
};

const Floor& floor_plan() {
  static const Floor f = [] {
    auto w = sim::load_world(ROBUTER_SHIPPED_WORLDS "/building_floor.toml");
    EXPECT_TRUE(w.ok()) << (w.ok() ? "" : w.error().describe());
    auto g = load_place_graph(ROBUTER_SHIPPED_WORLDS "/building_floor.places.toml");
    EXPECT_TRUE(g.ok()) << (g.ok() ? "" : g.error().describe());
    return Floor{w.ok() ? std::move(w).value() : sim::World{}, g.ok() ? std::move(g).value() : PlaceGraph{}};
  }();
  return f;
}

TEST(BuildingFloor, IsABuildingFloorAtRealSize) {
  const Floor& f = floor_plan();
  const sim::Box& b = f.world.bounds();
  EXPECT_GE(b.hi.x() - b.lo.x(), 60.0 - 0.2);
  EXPECT_GE(b.hi.y() - b.lo.y(), 40.0 - 0.2);
  int rooms = 0;
  for (const Place& p : f.graph.places()) rooms += p.name.rfind("room-", 0) == 0 ? 1 : 0;
  EXPECT_GE(rooms, 12);
  ASSERT_GE(f.world.doors.size(), 12u);
  double narrowest = std::numeric_limits<double>::infinity();
  for (const sim::Door& d : f.world.doors) narrowest = std::min(narrowest, d.width);
  EXPECT_GE(narrowest, 0.90 - 1e-9);
  EXPECT_LE(narrowest, 0.90 + 1e-9) << "90 cm doors are on the floor";
}

TEST(BuildingFloor, EveryCentreIsClearOfWallsAndFurniture) {
  const Floor& f = floor_plan();
  for (const Place& p : f.graph.places()) {
    double clear = std::numeric_limits<double>::infinity();
    for (const sim::Segment& s : f.world.segments()) clear = std::min(clear, sim::point_segment_distance(p.centre, s.a, s.b));
    EXPECT_GE(clear, 1.0) << p.name;
    EXPECT_EQ(f.world.obstacle_containing(p.centre), -1) << p.name;
  }
}

TEST(BuildingFloor, EveryDoorOfTheWorldIsADoorOfTheGraphWithItsWidth) {
  const Floor& f = floor_plan();
  for (const sim::Door& wd : f.world.doors) {
    const Door* match = nullptr;
    for (const Door& d : f.graph.doors())
      if ((d.at - wd.centre).norm() < 0.2) match = &d;
    ASSERT_NE(match, nullptr) << wd.name << " at (" << wd.centre.x() << ", " << wd.centre.y() << ")";
    EXPECT_NEAR(match->width, wd.width, 1e-6) << wd.name;
  }
}

TEST(BuildingFloor, TheStartAndTheGoalAreInPlacesJoinedByARouteOver30m) {
  const Floor& f = floor_plan();
  ASSERT_TRUE(f.world.start && f.world.goal);
  const auto from = f.graph.place_at(Vec2(f.world.start->x, f.world.start->y));
  const auto to = f.graph.place_at(*f.world.goal);
  ASSERT_TRUE(from && to);
  const PlaceRoute r = shortest_route(f.graph, *from, *to);
  ASSERT_TRUE(r.found);
  EXPECT_GE(r.length, 30.0);
  // Every place reaches every other (one connected floor).
  for (std::size_t i = 1; i < f.graph.places().size(); ++i)
    EXPECT_TRUE(shortest_route(f.graph, 0, i).found) << f.graph.places()[i].name;
}

}  // namespace
}  // namespace robuter::places
