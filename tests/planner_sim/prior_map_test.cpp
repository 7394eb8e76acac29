// SPDX-License-Identifier: GPL-3.0-or-later
// [planner] map_file: the firmware plans on an a-priori map; every broken map file stops robuterd.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "modules/planner/lib/map_file.hpp"
#include "tests/planner_sim/nav_harness.hpp"

namespace robuter {
namespace {

namespace fs = std::filesystem;

// The default world's map as `robuter-plan -w worlds/default.toml --save-map` writes it (world
// frame, 0.5 m around the walls, obstacles at count 10 of threshold 10, the rest never seen).
constexpr const char* kDefaultWorldMap = PLANNER_SIM_DATA "/default_world.map";

// (1) With the default world's map, the whole firmware's first plan from the world's start goes
// through the 90 cm door to the east room (5.6, 3.0): the file's geometry and walls are the
// planner's. (Driving it through is not yet done: issue #13 and docs/PLANNER.md "A-priori map".)
TEST(PlannerSimPriorMap, TheFirmwarePlansThroughThe90cmDoorOfTheDefaultWorldWithTheWorldsMap) {
  Config cfg;
  cfg.planner.map_file = kDefaultWorldMap;
  const char* keep = std::getenv("ROBUTER_PLANNER_PICTURES");  // by hand: a picture of every plan there
  test::SimFirmware fw(ROBUTER_WORLDS_DIR "/default.toml", cfg, {}, false, keep != nullptr ? keep : "");
  ASSERT_TRUE(fw.ok()) << fw.error();
  PlannerModule* planner = test::planner_of(fw);
  ASSERT_NE(planner, nullptr);
  const plan::OccupancyMap& map = planner->planner().map();
  EXPECT_EQ(map.width(), 183);  // the file's geometry, not the default 12 x 12 m
  EXPECT_EQ(map.height(), 142);
  EXPECT_EQ(map.threshold(), 2);  // [planner] hit_threshold judges the file's counts
  EXPECT_EQ(map.state(map.cell_of({4.5, 1.0})), plan::CellState::Occupied);  // the partition
  ASSERT_EQ(fw.ask("AC 15000 15000 0"), "ack");  // odometry = the world's (and the map's) frame
  fw.run_ticks(5);
  ASSERT_EQ(fw.ask("XG 56000 30000"), "ack");
  ASSERT_TRUE(fw.run_until([&] { return planner->state() == PlannerState::moving; }, 3000));
  bool through = false;
  const auto w = planner->planner().waypoints();
  for (std::size_t i = 1; i < w.size(); ++i) {
    if ((w[i - 1].pose.x - 4.5) * (w[i].pose.x - 4.5) <= 0.0 && w[i - 1].pose.x != w[i].pose.x) {
      EXPECT_NEAR(w[i].pose.y, 3.0, 0.45) << "crossed outside the door";
      through = true;
    }
  }
  EXPECT_TRUE(through);
  EXPECT_GT(w.size(), 50u);
}

// (1b) On the way to that door the ring's echoes from its jambs go to the jambs' cells: a jamb's
// corner met by the arc of an oblique sensor lies on a cell boundary, and a hit put in the free
// cell beside it (the arc looked at a cell apart) made the 90 cm door 5 cm narrower, too narrow
// for the body (the second replan was `unreachable`). Every cell of the doorway stays unoccupied
// until the robot's front reaches the door, and so do the cells 10 cm before and after it.
TEST(PlannerSimPriorMap, TheRingsEchoesFromTheJambsDoNotCloseTheDoor) {
  Config cfg;
  cfg.planner.map_file = kDefaultWorldMap;
  test::SimFirmware fw(ROBUTER_WORLDS_DIR "/default.toml", cfg);
  ASSERT_TRUE(fw.ok()) << fw.error();
  PlannerModule* planner = test::planner_of(fw);
  ASSERT_NE(planner, nullptr);
  const plan::OccupancyMap& map = planner->planner().map();
  std::vector<plan::Cell> doorway;  // centres in the partition (x 4.45-4.55 m) and 10 cm either side, between the jambs (y 2.55-3.45 m)
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x) {
      const plan::Point2 c = map.center({x, y});
      if (c.x > 4.35 && c.x < 4.65 && c.y > 2.55 && c.y < 3.45) doorway.push_back({x, y});
    }
  ASSERT_EQ(doorway.size(), 6u * 18u);
  for (const plan::Cell& c : doorway) ASSERT_NE(map.state(c), plan::CellState::Occupied) << c.x << " " << c.y;
  ASSERT_EQ(fw.ask("AC 15000 15000 0"), "ack");
  fw.run_ticks(5);
  ASSERT_EQ(fw.ask("XG 56000 30000"), "ack");
  const auto& robot = fw.sim().robot();
  bool at_door = false;
  for (int i = 0; i < 6'000 && !at_door; ++i) {
    fw.step();
    at_door = robot.pose().x > 3.7;  // the front face (0.695 m ahead of the axle) 5 cm from the partition
    for (const plan::Cell& c : doorway)
      ASSERT_NE(map.state(c), plan::CellState::Occupied) << "tick " << i << ": doorway cell at (" << map.center(c).x
                                                         << ", " << map.center(c).y << ") m marked";
    ASSERT_NE(planner->state(), PlannerState::unreachable) << "tick " << i;
  }
  EXPECT_TRUE(at_door) << "axle at (" << robot.pose().x << ", " << robot.pose().y << ") m";
}

// Runs robuterd, returns its exit status and what it printed (stdout and stderr).
std::pair<int, std::string> run_robuterd(const std::string& args) {
  const std::string cmd = std::string(ROBUTERD) + " " + args + " 2>&1";
  FILE* p = ::popen(cmd.c_str(), "r");
  if (p == nullptr) return {-1, "popen failed"};
  std::string out;
  char buf[512];
  while (std::fgets(buf, sizeof buf, p) != nullptr) out += buf;
  const int st = ::pclose(p);
  return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, out};
}

// A folder of its own per test: the configuration and the map files.
class PriorMapFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("robuter-prior-map-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "maps");
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) const { std::ofstream(dir_ / name) << text; }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

// A valid 4 x 3 map of 50 mm cells at (-100, -50) mm, one obstacle.
std::string small_map(const std::string& resolution = "0.05", const std::string& cells = "0a000000") {
  return "robuter-map 1\nwidth 4\nheight 3\nresolution " + resolution + "\norigin -0.1 -0.05\nthreshold 10\ndata\n" +
         cells + "\n........\n00000000\n";
}

// Decided: a relative map_file is relative to the configuration's folder, wherever robuterd
// runs from; the file's header gives the map; --check-config says so on its one line.
TEST_F(PriorMapFiles, ARelativePathIsTheConfigurationsFolderAndCheckConfigReportsTheFilesGeometry) {
  write("maps/room.map", small_map());
  write("robuterd.toml", "[planner]\nmap_file = \"maps/room.map\"\ncell_mm = 50\n");
  const auto [rc, out] = run_robuterd("--check-config --config " + path("robuterd.toml"));
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("is valid"), std::string::npos) << out;
  EXPECT_NE(out.find("planner.map_file " + path("maps/room.map") +
                     ": 4 x 3 cells of 50 mm from (-100, -50) mm, 1 obstacle cells (the file's geometry)"),
            std::string::npos)
      << out;
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1) << out;
}

// A broken map file or one the configuration contradicts: exit 2, one line naming the file (and
// the line), before anything runs.
struct BadMap {
  const char* name;    // test name
  const char* config;  // [planner] keys besides map_file
  const char* map;     // the map file's text; null: no file written
  const char* file;    // map_file as written in the configuration
  const char* want;    // expected in the message, after "DIR/"
};

class BrokenMapFile : public PriorMapFiles, public ::testing::WithParamInterface<BadMap> {};

TEST_P(BrokenMapFile, ExitsWithStatus2AndOneLineNamingTheFile) {
  const BadMap& c = GetParam();
  if (c.map != nullptr) write("maps/bad.map", c.map);
  write("robuterd.toml", std::string("[planner]\nmap_file = \"") + c.file + "\"\n" + c.config);
  for (const char* mode : {"--check-config", "--sim --ticks 1"}) {
    const auto [rc, out] = run_robuterd(std::string(mode) + " --config " + path("robuterd.toml"));
    EXPECT_EQ(rc, 2) << mode << ": " << out;
    EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1) << mode << ": " << out;
    EXPECT_NE(out.find("robuterd: configuration error: planner.map_file: " + dir_.string() + "/" + c.want),
              std::string::npos)
        << mode << ": " << out;
  }
}

const std::string kBigMap = [] {
  std::string s = "robuter-map 1\nwidth 600\nheight 600\nresolution 0.05\norigin 0 0\nthreshold 10\ndata\n";
  for (int y = 0; y < 600; ++y) s += std::string(1200, '.') + "\n";
  return s;
}();

INSTANTIATE_TEST_SUITE_P(
    PlannerSimPriorMap, BrokenMapFile,
    ::testing::Values(
        BadMap{"Missing", "", nullptr, "maps/none.map", "maps/none.map: cannot open: No such file or directory"},
        BadMap{"AFolder", "", nullptr, "maps", "maps: is a folder, not a file"},
        BadMap{"NotAMap", "", "P2\n4 3\n", "maps/bad.map", "maps/bad.map:1: not a robuter map (expected 'robuter-map 1')"},
        BadMap{"BadHeader", "", "robuter-map 1\nwidth four\n", "maps/bad.map", "maps/bad.map:2: bad width"},
        BadMap{"BadCell", "", "robuter-map 1\nwidth 2\nheight 1\nresolution 0.05\norigin 0 0\ndata\n0azz\n",
               "maps/bad.map", "maps/bad.map:7: bad cell 'zz' at column 1"},
        BadMap{"MissingRows", "", "robuter-map 1\nwidth 2\nheight 3\nresolution 0.05\norigin 0 0\ndata\n0000\n",
               "maps/bad.map", "maps/bad.map:7: unexpected end of file: missing map rows"},
        BadMap{"TooLargeForThePlanner", "", kBigMap.c_str(), "maps/bad.map",
               "maps/bad.map:2: a map of 360000 cells is too large for the rectangle planner (at most 262144)"},
        BadMap{"ResolutionMismatch", "cell_mm = 100\n", "robuter-map 1\nwidth 2\nheight 1\nresolution 0.05\norigin 0 0\ndata\n0000\n",
               "maps/bad.map", "maps/bad.map:4: resolution 50 mm disagrees with planner.cell_mm = 100 ("},
        BadMap{"ResolutionNotWholeMm", "", "robuter-map 1\nwidth 2\nheight 1\nresolution 0.0375\norigin 0 0\ndata\n0000\n",
               "maps/bad.map", "maps/bad.map:4: resolution 0.0375 m is not a whole number of mm from 10 to 500"},
        BadMap{"WidthMismatch", "map_width_mm = 12000\n",
               "robuter-map 1\nwidth 2\nheight 1\nresolution 0.05\norigin 0 0\ndata\n0000\n", "maps/bad.map",
               "maps/bad.map:2: width 2 cells (100 mm) disagrees with planner.map_width_mm = 12000 ("},
        BadMap{"OriginMismatch", "map_origin_x_mm = -6000\n",
               "robuter-map 1\nwidth 2\nheight 1\nresolution 0.05\norigin 0 0\ndata\n0000\n", "maps/bad.map",
               "maps/bad.map:5: origin x 0 mm disagrees with planner.map_origin_x_mm = -6000 ("},
        BadMap{"ACellTheThresholdsJudgeDifferently", "",
               "robuter-map 1\nwidth 2\nheight 2\nresolution 0.05\norigin 0 0\nthreshold 10\ndata\n0005\n0000\n",
               "maps/bad.map",
               "maps/bad.map:8: cell (1, 1) has count 5: free with the file's threshold 10 but an obstacle with "
               "planner.hit_threshold = 2"}),
    [](const ::testing::TestParamInfo<BadMap>& i) { return std::string(i.param.name); });

}  // namespace
}  // namespace robuter
