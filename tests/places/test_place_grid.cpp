// SPDX-License-Identifier: GPL-3.0-or-later
// Seed 003's local grid per place: cut from the map, its text, its files, applied to a map.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "modules/places/place_graph_file.hpp"
#include "modules/places/place_grid.hpp"
#include "modules/places/place_grid_memory.hpp"
#include "modules/places/wall_raster.hpp"

namespace robuter::places {
namespace {

using plan::Cell;
using plan::CellState;

// Two 1 m x 0.5 m rooms side by side (x 0-1 and 1-2, y 0-0.5), a 0.3 m door between them.
PlaceGraph two_small_rooms() {
  std::vector<Place> p{{"west", {{0, 0}, {1, 0}, {1, 0.5}, {0, 0.5}}, {0.5, 0.25}},
                       {"east", {{1, 0}, {2, 0}, {2, 0.5}, {1, 0.5}}, {1.5, 0.25}}};
  std::vector<Door> d{{"door", 0, 1, {1, 0.25}, 0.3}};
  return PlaceGraph(std::move(p), std::move(d));
}

// A 0.25 m map of 12 x 4 cells from (-0.5, -0.25): the west room is cells x 2..5, y 1..2.
plan::OccupancyMap small_map() {
  plan::OccupancyMap m(plan::MapGeometry{12, 4, 0.25, {-0.5, -0.25}});
  m.mark_free({2, 1});
  m.mark_free({3, 1});
  m.mark_occupied({5, 2});
  m.mark_occupied({4, 1});
  m.clear_changes();
  return m;
}

// Why: the grid is the place's bounding box on the map's cells (no margin here), in seed 003's
// characters, north row first; the robot's cell is 'P'; a margin widens it by whole cells.
TEST(PlaceGrid, CutIsTheBoundingBoxInSeed003Characters) {
  const PlaceGrid g = cut_place(two_small_rooms(), 0, small_map(), plan::Point2{0.1, 0.1}, 0.0);
  EXPECT_EQ(g.place, "west");
  EXPECT_EQ(g.width, 4);
  EXPECT_EQ(g.height, 2);
  EXPECT_DOUBLE_EQ(g.origin.x, 0.0);
  EXPECT_DOUBLE_EQ(g.origin.y, 0.0);
  ASSERT_TRUE(g.scanned_from.has_value());
  EXPECT_EQ(*g.scanned_from, (Cell{0, 0}));
  EXPECT_EQ(place_grid_text(g),
            "# robuter place grid: seed 003's characters, '.' unknown, '#' obstacle, ' ' free, 'P' the robot\n"
            "place west\n"
            "cell 0.25\n"
            "origin 0 0\n"
            "size 4 2\n"
            "scanned 0 0\n"
            "grid\n"
            "...#\n"
            "P #.\n");
  const PlaceGrid wide = cut_place(two_small_rooms(), 0, small_map(), plan::Point2{0.1, 0.1}, 0.25);
  EXPECT_EQ(wide.width, 6);
  EXPECT_EQ(wide.height, 4);
  EXPECT_DOUBLE_EQ(wide.origin.x, -0.25);
  EXPECT_EQ(wide.at(4, 2), CellState::Occupied) << "map cell (5, 2)";
}

// Why: the periodic path's cut writes into a buffer sized at start-up: within its capacity it
// allocates nothing and gives what cut_place gives; a box larger than the capacity is refused and
// the buffer left as it was.
TEST(PlaceGrid, CutIntoABufferSizedBefore) {
  const PlaceGraph g = two_small_rooms();
  const plan::OccupancyMap m = small_map();
  const PlaceBox box = place_box(g, 0, m.geometry(), 0.0);
  EXPECT_EQ(box.lo, (Cell{2, 1}));
  PlaceGrid buf;
  buf.cells.reserve(static_cast<std::size_t>(box.width * box.height));
  const CellState* data = buf.cells.data();
  ASSERT_TRUE(cut_place_into(g, 0, m, plan::Point2{0.1, 0.1}, buf, 0.0));
  EXPECT_EQ(buf.cells.data(), data) << "no new buffer";
  const PlaceGrid whole = cut_place(g, 0, m, plan::Point2{0.1, 0.1}, 0.0);
  EXPECT_EQ(buf.cells, whole.cells);
  EXPECT_EQ(buf.scanned_from, whole.scanned_from);
  EXPECT_TRUE(buf.place.empty()) << "the name is the writer's";
  const std::vector<CellState> before = buf.cells;
  EXPECT_FALSE(cut_place_into(g, 0, m, std::nullopt, buf, 0.5)) << "a wider box than the buffer holds";
  EXPECT_EQ(buf.cells, before);
  EXPECT_TRUE(buf.scanned_from.has_value());
}

// Why: cells of the box off the map are unknown; a robot off the grid gives no 'P'.
TEST(PlaceGrid, CellsOffTheMapAreUnknown) {
  plan::OccupancyMap m(plan::MapGeometry{3, 2, 0.25, {0.0, 0.0}});  // covers x 0-0.75 only
  for (int x = 0; x < 3; ++x) m.mark_free({x, 0});
  const PlaceGrid g = cut_place(two_small_rooms(), 0, m, plan::Point2{5.0, 5.0}, 0.0);
  ASSERT_EQ(g.width, 4);
  EXPECT_FALSE(g.scanned_from.has_value());
  EXPECT_EQ(g.at(0, 0), CellState::Free);
  EXPECT_EQ(g.at(3, 0), CellState::Unknown) << "off the map";
  EXPECT_NE(place_grid_text(g).find("scanned none\n"), std::string::npos);
}

// Why: text -> grid -> text is the identity, on every place of the shipped building floor cut
// from its wall raster (the largest grids a run makes), with a robot in each.
TEST(PlaceGrid, TextRoundTripsOnTheBuildingFloor) {
  auto graph = load_place_graph(std::string(ROBUTER_SHIPPED_WORLDS) + "/building_floor.places.toml");
  ASSERT_TRUE(graph.ok());
  const plan::OccupancyMap walls = wall_raster(graph.value(), 0.05);
  std::size_t obstacles = 0;
  for (std::size_t k = 0; k < graph.value().places().size(); ++k) {
    const Place& p = graph.value().places()[k];
    const PlaceGrid g = cut_place(graph.value(), k, walls, plan::Point2{p.centre.x(), p.centre.y()});
    ASSERT_TRUE(g.scanned_from.has_value()) << p.name;
    const std::string text = place_grid_text(g);
    const auto back = parse_place_grid(text, p.name + ".txt");
    ASSERT_TRUE(back.ok()) << back.error().text();
    EXPECT_EQ(back.value().cells, g.cells) << p.name;
    EXPECT_EQ(back.value().origin.x, g.origin.x) << p.name;
    EXPECT_EQ(back.value().origin.y, g.origin.y) << p.name;
    EXPECT_EQ(back.value().scanned_from, g.scanned_from) << p.name;
    EXPECT_EQ(place_grid_text(back.value()), text) << p.name;
    for (CellState s : g.cells) obstacles += s == CellState::Occupied;
  }
  EXPECT_GT(obstacles, 1000u) << "the walls are in the grids";
}

// Why: every broken file is one clear error naming its line; nothing is returned.
TEST(PlaceGrid, BrokenFilesAreErrorsWithTheirLine) {
  const std::string head = "place west\ncell 0.25\norigin 0 0\nsize 3 2\nscanned 0 0\ngrid\n";
  struct Case {
    std::string text;  // the file
    int line;          // the error's line
    std::string says;  // part of the message
  };
  const std::vector<Case> cases = {
      {head + "...\nP #\n", 0, ""},  // the good file (checked below)
      {head + "...\n", 7, "1 rows after 'grid', size says 2"},
      {head + "...\nP #\n...\n", 9, "3 rows"},
      {head + "...\nP\n", 8, "row of 1 characters"},
      {head + "..x\nP #\n", 7, "character 'x'"},
      {head + "..P\n  #\n", 7, "'P' at column 3"},
      {head + "...\n  #\n", 8, "holds no 'P'"},
      {"place west\ncell 0.25\norigin 0 0\nsize 3 2\nscanned 5 0\ngrid\n...\n   \n", 6, "off the grid"},
      {"place west\nplace east\n", 2, "given twice"},
      {"place we st\n", 1, "takes 1 value"},
      {"place w/e\n", 1, "place name"},
      {"place west\ncell -1\n", 2, "above 0"},
      {"place west\ncell 0.25\norigin 0 zero\n", 3, "two coordinates"},
      {"place west\ncell 0.25\norigin 0 0\nsize 0 2\n", 4, "whole numbers"},
      {"place west\ncell 0.25\norigin 0 0\nsize 3 2.5\n", 4, "whole numbers"},
      {"colour red\n", 1, "unknown key 'colour'"},
      {"place west\ncell 0.25\n", 2, "no 'grid' line"},
      {"place west\ncell 0.25\norigin 0 0\nscanned none\ngrid\n", 5, "'size' is missing"},
      {"place west\ncell 0.25\norigin 0 0\nsize 3 2\nscanned none\ngrid x\n", 6, "takes nothing"},
  };
  const auto good = parse_place_grid(cases[0].text, "w.txt");
  ASSERT_TRUE(good.ok()) << good.error().text();
  EXPECT_EQ(good.value().at(0, 0), CellState::Free) << "the 'P' is free";
  EXPECT_EQ(good.value().at(2, 0), CellState::Occupied);
  EXPECT_EQ(good.value().at(1, 1), CellState::Unknown);
  for (std::size_t k = 1; k < cases.size(); ++k) {
    const auto r = parse_place_grid(cases[k].text, "w.txt");
    ASSERT_FALSE(r.ok()) << "case " << k;
    EXPECT_EQ(r.error().file, "w.txt");
    EXPECT_EQ(r.error().line, cases[k].line) << "case " << k << ": " << r.error().text();
    EXPECT_NE(r.error().message.find(cases[k].says), std::string::npos) << "case " << k << ": " << r.error().text();
  }
}

// Why: a file is written whole (a temporary renamed) and read back; a folder that does not exist
// (made missing by the test itself) is an error and leaves nothing behind.
TEST(PlaceGrid, SavedAndLoaded) {
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / ("place_grid_test_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const PlaceGrid g = cut_place(two_small_rooms(), 0, small_map(), plan::Point2{0.1, 0.1}, 0.0);
  const std::string path = place_grid_path(dir.string(), g.place);
  EXPECT_EQ(path, (dir / "west.txt").string());
  ASSERT_TRUE(save_place_grid(g, path).ok());
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  const auto back = load_place_grid(path);
  ASSERT_TRUE(back.ok()) << back.error().text();
  EXPECT_EQ(back.value().cells, g.cells);
  const std::string missing = (dir / "gone" / "west.txt").string();
  const auto bad = save_place_grid(g, missing);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().file, missing);
  EXPECT_FALSE(load_place_grid(missing).ok());
  std::filesystem::remove_all(dir);
}

// Why: [places] load_grids reads `<dir>/<place>.txt` at start-up, a folder anyone may write to:
// a FIFO there must not hang the firmware, nor a huge file (or /dev/zero behind a link) fill its
// memory. Each is refused with the reason, like every other file robuterd reads.
TEST(PlaceGrid, AFifoAFolderOrAHugeFileIsRefusedWithoutReadingIt) {
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / ("place_grid_odd_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string fifo = (dir / "fifo.txt").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto f = load_place_grid(fifo);  // opened for reading with no writer: used to wait for ever
  ASSERT_FALSE(f.ok());
  EXPECT_NE(f.error().text().find("not a regular file"), std::string::npos) << f.error().text();
  std::filesystem::create_directories(dir / "folder.txt");
  const auto d = load_place_grid((dir / "folder.txt").string());
  ASSERT_FALSE(d.ok());
  EXPECT_NE(d.error().text().find("folder"), std::string::npos) << d.error().text();
  const std::string huge = (dir / "huge.txt").string();
  { std::ofstream(huge).put('x'); }
  std::filesystem::resize_file(huge, 4ull << 30);  // 4 GiB, sparse: no disk used
  const auto h = load_place_grid(huge);
  ASSERT_FALSE(h.ok());
  EXPECT_NE(h.error().text().find("larger than"), std::string::npos) << h.error().text();
  std::filesystem::create_symlink("/dev/zero", dir / "zero.txt");
  const auto z = load_place_grid((dir / "zero.txt").string());
  ASSERT_FALSE(z.ok());
  EXPECT_NE(z.error().text().find("not a regular file"), std::string::npos) << z.error().text();
  std::filesystem::remove_all(dir);
}

// Why: a loaded grid fills what the map does not know (obstacles at the threshold: one miss can
// clear a remembered obstacle that moved); what the map knows stays; a grid on other cells is
// refused and changes nothing.
TEST(PlaceGrid, AppliedWhereTheMapDoesNotKnow) {
  const PlaceGrid g = cut_place(two_small_rooms(), 0, small_map(), plan::Point2{0.1, 0.1}, 0.0);
  plan::OccupancyMap m(plan::MapGeometry{12, 4, 0.25, {-0.5, -0.25}});
  m.mark_occupied({2, 1});  // the map knows an obstacle where the grid says free: it stays
  const auto n = apply_place_grid(g, m);
  ASSERT_TRUE(n.ok());
  EXPECT_EQ(n.value(), 3u) << "free (3, 1), obstacles (4, 1) and (5, 2)";
  EXPECT_EQ(m.state({2, 1}), CellState::Occupied);
  EXPECT_EQ(m.state({3, 1}), CellState::Free);
  EXPECT_EQ(m.state({4, 1}), CellState::Occupied);
  EXPECT_EQ(m.count({4, 1}), m.threshold());
  EXPECT_EQ(m.state({5, 2}), CellState::Occupied);
  EXPECT_EQ(m.state({2, 2}), CellState::Unknown);
  plan::OccupancyMap other(plan::MapGeometry{12, 4, 0.20, {-0.5, -0.25}});
  EXPECT_FALSE(apply_place_grid(g, other).ok());
  plan::OccupancyMap shifted(plan::MapGeometry{12, 4, 0.25, {-0.4, -0.25}});
  EXPECT_FALSE(apply_place_grid(g, shifted).ok());
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 12; ++x) {
      EXPECT_EQ(other.state({x, y}), CellState::Unknown);
      EXPECT_EQ(shifted.state({x, y}), CellState::Unknown);
    }
}

// Why: a later run's memory ([places] load_grids): each place's saved file is read and applied
// to one map of the floor; places without a file are unknown; a broken file, a file holding
// another place's grid, or a grid on other cells stops it with the file named.
TEST(GridMemory, SavedGridsReadBackIntoOneMapOfTheFloor) {
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / ("grid_memory_test_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const PlaceGraph rooms = two_small_rooms();
  const plan::MapGeometry floor{12, 4, 0.25, {-0.5, -0.25}};
  const auto none = load_grid_memory(rooms, dir.string(), floor, 2);
  ASSERT_TRUE(none.ok()) << none.error().text();
  EXPECT_EQ(none.value().grids, 0u);
  ASSERT_TRUE(save_place_grid(cut_place(rooms, 0, small_map(), plan::Point2{0.1, 0.1}, 0.0),
                              place_grid_path(dir.string(), "west")).ok());
  std::ofstream(dir / "notes.txt") << "not a place: not read\n";
  const auto one = load_grid_memory(rooms, dir.string(), floor, 2);
  ASSERT_TRUE(one.ok()) << one.error().text();
  EXPECT_EQ(one.value().grids, 1u);
  const plan::OccupancyMap& m = one.value().map;
  EXPECT_EQ(m.state({3, 1}), CellState::Free);
  EXPECT_EQ(m.state({4, 1}), CellState::Occupied);
  EXPECT_EQ(m.state({5, 2}), CellState::Occupied);
  EXPECT_EQ(m.state({8, 1}), CellState::Unknown) << "the east room: no file";
  EXPECT_TRUE(m.changes().empty()) << "a map at rest";
  // The east room's file holding the west room's grid: refused, naming the file.
  std::filesystem::copy_file(dir / "west.txt", dir / "east.txt");
  const auto swapped = load_grid_memory(rooms, dir.string(), floor, 2);
  ASSERT_FALSE(swapped.ok());
  EXPECT_EQ(swapped.error().file, (dir / "east.txt").string());
  std::filesystem::remove(dir / "east.txt");
  // On other cells: refused.
  const auto other = load_grid_memory(rooms, dir.string(), plan::MapGeometry{12, 4, 0.20, {-0.5, -0.25}}, 2);
  ASSERT_FALSE(other.ok());
  EXPECT_EQ(other.error().file, (dir / "west.txt").string());
  // A broken file: refused with its line.
  std::ofstream(dir / "west.txt", std::ios::app) << "extra row\n";
  const auto broken = load_grid_memory(rooms, dir.string(), floor, 2);
  ASSERT_FALSE(broken.ok());
  EXPECT_EQ(broken.error().file, (dir / "west.txt").string());
  EXPECT_GT(broken.error().line, 0);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace robuter::places
