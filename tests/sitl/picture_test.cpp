// SPDX-License-Identifier: GPL-3.0-or-later
// Pictures from the command line: robuter-sim render (PNG and SVG, bad arguments) and
// robuterd --sim --picture; the files must be real pictures with content, ≥ 1000 px wide, and
// robuterd's picture must lay out its title, legend, scale bar and axes without overlap.
#include <gtest/gtest.h>

#include <cairo.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "hal/sitl/sim_picture.hpp"
#include "tests/support/layout_check.hpp"
#include "tests/support/missing_path.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

const std::string kBin = ROBUTER_BIN_DIR;
const std::string kOut = ROBUTER_SITL_TEST_OUT;
const std::string kWorld = std::string(ROBUTER_WORLDS_DIR) + "/default.toml";

// Runs a shell command quietly; its exit status.
int run(const std::string& cmd) {
  const int s = std::system((cmd + " >/dev/null 2>&1").c_str());
  return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Fraction of a PNG's pixels that differ from its top-left pixel (the background); -1 if the
// file is not a PNG cairo can read.
double ink(const std::string& path, int& width, int& height) {
  cairo_surface_t* s = cairo_image_surface_create_from_png(path.c_str());
  if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(s);
    return -1.0;
  }
  width = cairo_image_surface_get_width(s);
  height = cairo_image_surface_get_height(s);
  const int stride = cairo_image_surface_get_stride(s);
  const unsigned char* data = cairo_image_surface_get_data(s);
  const auto bg = *reinterpret_cast<const std::uint32_t*>(data);
  long differ = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) differ += *reinterpret_cast<const std::uint32_t*>(data + y * stride + 4 * x) != bg;
  cairo_surface_destroy(s);
  return static_cast<double>(differ) / (static_cast<double>(width) * height);
}

TEST(Pictures, RobuterSimRendersAPng) {
  const std::string out = kOut + "/render_ring.png";
  std::filesystem::remove(out);
  ASSERT_EQ(run(kBin + "/robuter-sim render --world " + kWorld + " --ring --pan-tilt 30 -o " + out), 0);
  int w = 0, h = 0;
  const double f = ink(out, w, h);
  EXPECT_EQ(w, 1000);  // the default: 1000 px wide, the scale filling the plot
  EXPECT_GT(h, 400);
  EXPECT_GT(f, 0.05);  // walls, robot, 24 beams: plenty of non-background pixels
  EXPECT_LT(f, 0.95);
}

TEST(Pictures, RobuterSimRendersAnSvgAtAGivenPose) {
  const std::string out = kOut + "/render_pose.svg";
  std::filesystem::remove(out);
  ASSERT_EQ(run(kBin + "/robuter-sim render --world " + kWorld + " --pose 6.0,3.0,180 --ring -o " + out), 0);
  const std::string svg = slurp(out);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  std::size_t paths = 0;
  for (std::size_t p = svg.find("<path"); p != std::string::npos; p = svg.find("<path", p + 1)) ++paths;
  EXPECT_GT(paths, 50u);
  EXPECT_GT(svg.size(), 20000u);
}

TEST(Pictures, RobuterSimRefusesBadArguments) {
  const robuter::test::MissingPaths paths;  // a world file that is not there, whatever this machine holds
  EXPECT_NE(run(kBin + "/robuter-sim render --world " + paths.missing("world.toml") + " -o " + kOut + "/x.png"), 0);
  EXPECT_NE(run(kBin + "/robuter-sim render --world " + kWorld + " -o " + kOut + "/x.jpg"), 0);
  EXPECT_NE(run(kBin + "/robuter-sim render --world " + kWorld + " --pose 1,2 -o " + kOut + "/x.png"), 0);
  EXPECT_NE(run(kBin + "/robuter-sim render --world " + kWorld + " --pose 0.1,0.1,0 -o " + kOut + "/x.png"), 0);
  EXPECT_NE(run(kBin + "/robuter-sim render --world " + kWorld), 0);
}

// Issue #17: the building floor with its place graph and a route drawn over it; the graph's
// ink is there (the same picture without it has fewer coloured pixels); bad --places/--route refused.
TEST(Pictures, RobuterSimDrawsThePlaceGraphAndARoute) {
  const std::string floor = std::string(ROBUTER_WORLDS_DIR) + "/building_floor.toml";
  const std::string graph = std::string(ROBUTER_WORLDS_DIR) + "/building_floor.places.toml";
  const std::string bare = kOut + "/floor_bare.png", drawn = kOut + "/floor_places.png";
  std::filesystem::remove(drawn);
  ASSERT_EQ(run(kBin + "/robuter-sim render --world " + floor + " -o " + bare), 0);
  ASSERT_EQ(run(kBin + "/robuter-sim render --world " + floor + " --places " + graph +
                " --route corridor-ew-1,room-16 -o " + drawn), 0);
  int w = 0, h = 0, w2 = 0, h2 = 0;
  const double without = ink(bare, w, h), with = ink(drawn, w2, h2);
  EXPECT_EQ(w, w2);
  EXPECT_GT(with, without + 0.02) << "places, doors, centres and the route add ink";
  EXPECT_NE(run(kBin + "/robuter-sim render --world " + floor + " --route corridor-ew-1,room-16 -o " + drawn), 0);
  EXPECT_NE(run(kBin + "/robuter-sim render --world " + floor + " --places " + graph + " --route corridor-ew-1 -o " + drawn), 0);
  EXPECT_NE(run(kBin + "/robuter-sim render --world " + floor + " --places " + graph + " --route a,b -o " + drawn), 0);
  EXPECT_NE(run(kBin + "/robuter-sim render --world " + floor + " --places " + floor + " -o " + drawn), 0)
      << "a world is not a place graph";
}

// Issue #17: place grids (seed 003's grid per place) drawn at their place over the floor, with
// the graph: more ink than the graph alone; a broken grid file is refused with its line.
TEST(Pictures, RobuterSimDrawsPlaceGrids) {
  const std::string floor = std::string(ROBUTER_WORLDS_DIR) + "/building_floor.toml";
  const std::string graph = std::string(ROBUTER_WORLDS_DIR) + "/building_floor.places.toml";
  const std::string grid = kOut + "/corridor-ew-1.txt", broken = kOut + "/broken-grid.txt";
  {
    std::ofstream out(grid);
    out << "place corridor-ew-1\ncell 0.05\norigin 0 18.8\nsize 200 48\nscanned 60 24\ngrid\n";
    for (int r = 0; r < 48; ++r) {
      std::string row(200, r == 0 || r == 47 ? '#' : ' ');
      if (r == 48 - 1 - 24) row[60] = 'P';
      out << row << "\n";
    }
    std::ofstream bad(broken);
    bad << "place corridor-ew-1\ncell 0.05\norigin 0 18.8\nsize 3 1\nscanned none\ngrid\n..\n";
  }
  const std::string alone = kOut + "/floor_graph.png", drawn = kOut + "/floor_grids.png";
  std::filesystem::remove(drawn);
  ASSERT_EQ(run(kBin + "/robuter-sim render --world " + floor + " --places " + graph + " -o " + alone), 0);
  ASSERT_EQ(run(kBin + "/robuter-sim render --world " + floor + " --places " + graph + " --place-grid " + grid +
                " -o " + drawn), 0);
  int w = 0, h = 0, w2 = 0, h2 = 0;
  const double without = ink(alone, w, h), with = ink(drawn, w2, h2);
  EXPECT_EQ(w, w2);
  EXPECT_GT(with, without + 0.003) << "the grid's free cells and walls add ink";
  EXPECT_NE(run(kBin + "/robuter-sim render --world " + floor + " --place-grid " + broken + " -o " + drawn), 0);
  const std::string why = kOut + "/broken-grid.err";
  std::system((kBin + "/robuter-sim render --world " + floor + " --place-grid " + broken + " -o " + drawn + " 2>" + why).c_str());
  EXPECT_NE(slurp(why).find("broken-grid.txt:7:"), std::string::npos) << slurp(why);
}

TEST(Pictures, RobuterdWritesAPictureAtExit) {
  const std::string out = kOut + "/robuterd_exit.png";
  std::filesystem::remove(out);
  ASSERT_EQ(run(kBin + "/robuterd --sim --sonar-model ideal --speed max --ticks 300 --ptu-sweep --picture " + out), 0);
  int w = 0, h = 0;
  const double f = ink(out, w, h);
  EXPECT_GE(w, 1000);
  EXPECT_GT(f, 0.05);
  const std::string svg = kOut + "/robuterd_exit.svg";
  ASSERT_EQ(run(kBin + "/robuterd --sim --sonar-model ideal --speed max --ticks 300 --picture " + svg), 0);
  EXPECT_NE(slurp(svg).find("<svg"), std::string::npos);
}

TEST(Pictures, RobuterdRefusesAPictureItCannotWrite) {
  EXPECT_EQ(run(kBin + "/robuterd --sim --sonar-model ideal --speed max --ticks 10 --picture " + kOut + "/x.jpg"), 2);
}

// The scene robuterd draws at exit, from a simulated robot: its layout explains it (title with
// the world, the time and the outcome; legend; scale bar; axes; sensor numbers apart).
TEST(Pictures, RobuterdPictureIsExplained) {
  const robuter::Config cfg;
  const robuter::hal::SimRobot robot(cfg, robuter::hal::SimOptions{});
  ASSERT_FALSE(robot.error());
  std::array<std::uint16_t, robuter::hal::kRingSensors> mm{};
  mm.fill(900);
  const robuter::test::TempDir dir;
  const auto laid = robuter::hal::write_sim_picture(robot, mm, 0, "no emergency latched", dir.file("exit.png"));
  ASSERT_TRUE(laid.ok()) << laid.error().describe();
  robuter::test::expect_explained(laid.value());
  const auto* title = laid.value().find(robuter::picture::Kind::title, "robuterd --sim");
  ASSERT_NE(title, nullptr);
  EXPECT_NE(title->text.find("no emergency latched"), std::string::npos) << title->text;
  EXPECT_NE(laid.value().find(robuter::picture::Kind::legend, "ring sonar: cone to its echo"), nullptr);
  EXPECT_GE(laid.value().of(robuter::picture::Kind::label).size(), 12u);  // most of the 24 numbers
  robuter::hal::release_picture_caches();  // fontconfig's caches, for LeakSanitizer
}

}  // namespace
