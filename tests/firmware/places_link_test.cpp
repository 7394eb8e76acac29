// SPDX-License-Identifier: GPL-3.0-or-later
// XN and XI on the whole firmware: the building floor's place graph ([places] file), the robot's
// place from its odometry, every place's number, name, centre and neighbours; without a graph: unavailable.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "modules/firmware/sim_firmware.hpp"
#include "modules/places/place_graph_file.hpp"

namespace robuter::test {
namespace {

Config floor_config() {
  Config cfg;
  cfg.places.file = ROBUTER_SHIPPED_WORLDS "/building_floor.places.toml";
  return cfg;
}

TEST(PlacesLink, XNFollowsTheOdometryAndXIListsEveryPlace) {
  SimFirmware fw(ROBUTER_SHIPPED_WORLDS "/building_floor.toml", floor_config());
  ASSERT_TRUE(fw.ok()) << fw.error();
  auto g = places::load_place_graph(ROBUTER_SHIPPED_WORLDS "/building_floor.places.toml");
  ASSERT_TRUE(g.ok());
  const places::PlaceGraph& graph = g.value();
  const std::string count = std::to_string(graph.places().size());
  // Set the odometry to the world's start (3.0, 20.05): the west end of the corridor.
  ASSERT_EQ(fw.ask("AC 30000 200500 0"), "ack");
  fw.run_ticks(5);
  const auto start = graph.place_at({3.0, 20.05});
  ASSERT_TRUE(start);
  EXPECT_EQ(fw.ask("XN"), "N " + count + " " + std::to_string(*start + 1) + " " + graph.places()[*start].name);
  // Each place's centre: XN there names it, XI gives it back.
  for (std::size_t i = 0; i < graph.places().size(); ++i) {
    const places::Place& p = graph.places()[i];
    const long x = std::lround(p.centre.x() * 1e4), y = std::lround(p.centre.y() * 1e4);
    ASSERT_EQ(fw.ask("AC " + std::to_string(x) + " " + std::to_string(y) + " 0"), "ack");
    EXPECT_EQ(fw.ask("XN"), "N " + count + " " + std::to_string(i + 1) + " " + p.name);
    std::string want = "I " + std::to_string(i + 1) + " " + p.name + " " + std::to_string(x) + " " + std::to_string(y) + " " +
                       std::to_string(graph.doors_of(i).size());
    for (const std::size_t d : graph.doors_of(i)) {
      const places::Door& door = graph.doors()[d];
      want += " " + std::to_string((door.a == i ? door.b : door.a) + 1);
    }
    EXPECT_EQ(fw.ask("XI " + std::to_string(i + 1)), want);
  }
  ASSERT_EQ(fw.ask("AC -100000 -100000 0"), "ack");  // 10 m outside the floor
  EXPECT_EQ(fw.ask("XN"), "N " + count + " 0 -");
  ASSERT_EQ(fw.ask("XB1"), "ack");
  EXPECT_EQ(fw.ask("XI " + std::to_string(graph.places().size() + 1)), "error 4 out-of-range");
  EXPECT_EQ(fw.ask("XI 0"), "error 4 out-of-range");
}

TEST(PlacesLink, WithoutAPlaceGraphXNAndXIAreUnavailable) {
  SimFirmware fw(ROBUTER_SHIPPED_WORLDS "/default.toml", Config{});
  ASSERT_TRUE(fw.ok()) << fw.error();
  ASSERT_EQ(fw.ask("XB1"), "ack");
  EXPECT_EQ(fw.ask("XN"), "error 12 unavailable");
  EXPECT_EQ(fw.ask("XI 1"), "error 12 unavailable");
  EXPECT_EQ(fw.ask("BO").value_or("").substr(0, 2), "S ") << "the link goes on";
}

TEST(PlacesLink, ABrokenPlaceFileIsAStartUpErrorWithItsLine) {
  Config cfg;
  cfg.places.file = ROBUTER_SHIPPED_WORLDS "/building_floor.toml";  // a world, not a place graph
  SimFirmware fw(ROBUTER_SHIPPED_WORLDS "/building_floor.toml", cfg);
  ASSERT_FALSE(fw.ok());
  EXPECT_NE(fw.error().find("places.file"), std::string::npos) << fw.error();
  EXPECT_NE(fw.error().find("building_floor.toml:1: missing [places]"), std::string::npos) << fw.error();
}

}  // namespace
}  // namespace robuter::test
