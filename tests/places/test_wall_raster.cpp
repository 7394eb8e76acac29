// SPDX-License-Identifier: GPL-3.0-or-later
// The walls a place graph implies: every place edge but its doors' openings, on the wall's side.
#include <gtest/gtest.h>

#include "modules/places/place_graph_file.hpp"
#include "modules/places/wall_raster.hpp"

#include <cmath>

namespace robuter::places {
namespace {

// Two 4 m squares side by side (x 0-4 and 4-8), a 1.0 m door in their shared edge at (4, 2).
PlaceGraph two_rooms_4m() {
  std::vector<Place> p{{"west", {{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {2, 2}},
                       {"east", {{4, 0}, {8, 0}, {8, 4}, {4, 4}}, {6, 2}}};
  std::vector<Door> d{{"door", 0, 1, {4, 2}, 1.0}};
  return PlaceGraph(std::move(p), std::move(d));
}

TEST(WallRaster, EdgesButTheDoorOnTheWallSide) {
  const plan::OccupancyMap m = wall_raster(two_rooms_4m(), 0.05, 1.0);
  auto at = [&](double x, double y) { return m.state(m.cell_of({x, y})); };
  EXPECT_EQ(m.resolution(), 0.05);
  EXPECT_DOUBLE_EQ(m.geometry().origin.x, -1.0);
  // The outer walls: the cells just outside the places; inside, unknown.
  EXPECT_EQ(at(2.0, -0.025), plan::CellState::Occupied);
  EXPECT_EQ(at(2.0, 4.025), plan::CellState::Occupied);
  EXPECT_EQ(at(-0.025, 2.0), plan::CellState::Occupied);
  EXPECT_EQ(at(2.0, 0.025), plan::CellState::Unknown);
  EXPECT_EQ(at(2.0, 2.0), plan::CellState::Unknown);
  // The shared edge: both sides' cells, but not in the door's opening (y 1.5 - 2.5), edges included.
  EXPECT_EQ(at(3.975, 1.0), plan::CellState::Occupied);
  EXPECT_EQ(at(4.025, 1.0), plan::CellState::Occupied);
  EXPECT_EQ(at(3.975, 1.475), plan::CellState::Occupied) << "the cell just below the opening";
  for (double y = 1.525; y < 2.5; y += 0.05) {
    EXPECT_EQ(at(3.975, y), plan::CellState::Unknown) << y;
    EXPECT_EQ(at(4.025, y), plan::CellState::Unknown) << y;
  }
  EXPECT_EQ(at(3.975, 2.525), plan::CellState::Occupied) << "the cell just above the opening";
}

TEST(WallRaster, DoorOpeningsAreTheCellsInsideTheOpening) {
  const std::vector<plan::Point2> cells = door_openings(two_rooms_4m(), wall_raster(two_rooms_4m(), 0.05), 0.35);
  ASSERT_FALSE(cells.empty());
  for (const plan::Point2& c : cells) {
    EXPECT_LE(std::abs(c.y - 2.0), 0.475 + 1e-9) << c.y;
    EXPECT_LE(std::abs(c.x - 4.0), 0.35 + 1e-9) << c.x;
  }
  // 19 rows across the 1.0 m opening (centres 1.525 ... 2.475), 14 columns within 0.35 m.
  EXPECT_EQ(cells.size(), 19u * 14u);
}

// Why: on the shipped floor every door keeps an opening at least as wide as the body (0.70 m)
// minus nothing: its middle row of cells is in the openings, none of them on a wall.
TEST(WallRaster, TheBuildingFloorsDoorsStayOpen) {
  auto loaded = load_place_graph(ROBUTER_SHIPPED_WORLDS "/building_floor.places.toml");
  ASSERT_TRUE(loaded.ok());
  const PlaceGraph& g = loaded.value();
  const plan::OccupancyMap m = wall_raster(g, 0.05);
  const std::vector<plan::Point2> open = door_openings(g, m);
  for (const plan::Point2& c : open) EXPECT_NE(m.state(m.cell_of(c)), plan::CellState::Occupied) << c.x << ", " << c.y;
  for (const Door& d : g.doors()) {
    const plan::Cell mid = m.cell_of({d.at.x(), d.at.y()});
    EXPECT_NE(m.state(mid), plan::CellState::Occupied) << d.name;
    std::size_t near = 0;  // opening cells within the door's half width
    for (const plan::Point2& c : open)
      if (std::hypot(c.x - d.at.x(), c.y - d.at.y()) <= d.width / 2.0) ++near;
    EXPECT_GE(near, static_cast<std::size_t>(std::floor(0.70 / 0.05))) << d.name;
  }
}

}  // namespace
}  // namespace robuter::places
