// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the file loaders: thesis parameter and environment files, saved maps; clear errors.
#include <gtest/gtest.h>

#include "modules/planner/lib/map_file.hpp"
#include "modules/planner/lib/planner.hpp"
#include "modules/planner/lib/thesis_files.hpp"
#include "tests/planner/test_util.hpp"
#include "tests/support/missing_path.hpp"

namespace robuter::plan {
namespace {

TEST(ThesisParameters, ParsesTheFiveLines) {
  const auto p = parse_parameters("0.30\n0.2\n90\n1.5 2.5\n10 12.25\n", "p.txt");
  ASSERT_TRUE(p.ok()) << p.error().text();
  EXPECT_DOUBLE_EQ(p->radius, 0.30);
  EXPECT_DOUBLE_EQ(p->speed, 0.2);
  EXPECT_DOUBLE_EQ(p->heading_deg, 90.0);
  EXPECT_DOUBLE_EQ(p->start.x, 1.5);
  EXPECT_DOUBLE_EQ(p->start.y, 2.5);
  EXPECT_DOUBLE_EQ(p->goal.x, 10.0);
  EXPECT_DOUBLE_EQ(p->goal.y, 12.25);
}

TEST(ThesisParameters, ErrorsNameFileAndLine) {
  auto e = parse_parameters("0.30\n0.2\n90\n1.5 abc\n10 12\n", "p.txt");
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error().file, "p.txt");
  EXPECT_EQ(e.error().line, 4);
  EXPECT_NE(e.error().text().find("start y"), std::string::npos) << e.error().text();
  e = parse_parameters("0.30\n0.2\n90\n1.5 2\n", "p.txt");
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error().message.find("end of file"), std::string::npos);
  EXPECT_NE(e.error().message.find("goal x"), std::string::npos);
  e = parse_parameters("0.30\n0.2\n90\n1.5 2\n3 4\n5\n", "p.txt");
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error().line, 6);
  EXPECT_NE(e.error().message.find("trailing"), std::string::npos);
  e = parse_parameters("-1\n0.2\n90\n1.5 2\n3 4\n", "p.txt");
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error().line, 1);
}

TEST(ThesisParameters, MissingFileIsAnError) {
  const robuter::test::MissingPaths paths;
  const std::string file = paths.missing("params.txt");
  const auto e = load_parameters(file);
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error().file, file);
  EXPECT_NE(e.error().text().find("cannot open"), std::string::npos);
}

TEST(ThesisEnvironment, ParsesPolygons) {
  const auto env = parse_environment("2\n3\n0 0\n1 0\n0 1\n2\n2 2\n3 3\n", "e.txt");
  ASSERT_TRUE(env.ok()) << env.error().text();
  ASSERT_EQ(env->size(), 2u);
  EXPECT_EQ((*env)[0].vertices.size(), 3u);
  EXPECT_DOUBLE_EQ((*env)[1].vertices[1].y, 3.0);
  const auto empty = parse_environment("0\n", "e.txt");
  ASSERT_TRUE(empty.ok());
  EXPECT_TRUE(empty->empty());
}

TEST(ThesisEnvironment, MalformedFilesGiveClearErrors) {
  struct Case {
    const char* text;
    int line;
    const char* words;
  };
  const Case cases[] = {
      {"", 1, "number of obstacles"},
      {"x\n", 1, "number of obstacles"},
      {"-2\n", 1, "bad number of obstacles"},
      {"1\n0\n", 2, "bad vertex count"},
      {"1\n3\n0 0\n1 0\n", 4, "vertex 3 of obstacle 1"},
      {"1\n2\n0 0\n1 zz\n", 4, "y of vertex 2"},
      {"2\n1\n0 0\n", 3, "vertex count of obstacle 2"},
      {"1\n1\n0 0\n7\n", 4, "trailing"},
  };
  for (const Case& c : cases) {
    const auto r = parse_environment(c.text, "env.txt");
    ASSERT_FALSE(r.ok()) << c.text;
    EXPECT_EQ(r.error().file, "env.txt");
    EXPECT_EQ(r.error().line, c.line) << c.text << " -> " << r.error().text();
    EXPECT_NE(r.error().message.find(c.words), std::string::npos) << r.error().text();
  }
}

TEST(ThesisEnvironment, EdgesAreRasterisedNotInteriors) {
  OccupancyMap m(MapGeometry{20, 20, 0.05, {}});
  rasterise_polygons(m, {Polygon{{{0.125, 0.125}, {0.625, 0.125}, {0.625, 0.625}, {0.125, 0.625}}}});
  for (int i = 2; i <= 12; ++i) {
    EXPECT_EQ(m.state({i, 2}), CellState::Occupied) << i;
    EXPECT_EQ(m.state({i, 12}), CellState::Occupied) << i;
    EXPECT_EQ(m.state({2, i}), CellState::Occupied) << i;
    EXPECT_EQ(m.state({12, i}), CellState::Occupied) << i;
  }
  EXPECT_EQ(m.state({7, 7}), CellState::Unknown);
  // Far-away and partly outside polygons are clipped, not walked.
  rasterise_polygons(m, {Polygon{{{-1e9, 0.325}, {1e9, 0.325}}}});
  EXPECT_EQ(m.state({19, 6}), CellState::Occupied);
}

TEST(ThesisEnvironment, LabFileLoads) {
  const auto env = load_environment(std::string(PLANNER_TEST_DATA) + "/lab.env");
  ASSERT_TRUE(env.ok()) << env.error().text();
  EXPECT_EQ(env->size(), 5u);
}

TEST(MapFile, RoundTrip) {
  OccupancyMap m(MapGeometry{7, 5, 0.1, {-0.5, 1.25}}, 3);
  m.set_count({0, 0}, 0);
  m.set_count({6, 4}, 254);
  m.set_count({3, 2}, 2);
  const std::string text = format_map(m);
  const auto back = parse_map(text, "m.map");
  ASSERT_TRUE(back.ok()) << back.error().text();
  EXPECT_EQ(back->width(), 7);
  EXPECT_EQ(back->height(), 5);
  EXPECT_DOUBLE_EQ(back->resolution(), 0.1);
  EXPECT_DOUBLE_EQ(back->geometry().origin.x, -0.5);
  EXPECT_EQ(back->threshold(), 3);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 7; ++x) EXPECT_EQ(back->count({x, y}), m.count({x, y}));
  EXPECT_TRUE(back->changes().empty());
  const std::string path = test::temp_file("roundtrip.map", text);
  const auto loaded = load_map(path);
  ASSERT_TRUE(loaded.ok());
  EXPECT_EQ(loaded->count({6, 4}), 254);
}

TEST(MapFile, MalformedFilesGiveClearErrors) {
  const std::string head = "robuter-map 1\nwidth 2\nheight 2\nresolution 0.05\norigin 0 0\nthreshold 10\ndata\n";
  struct Case {
    std::string text;
    int line;
    const char* words;
  };
  const Case cases[] = {
      {"P2\n", 1, "not a robuter map"},
      {"robuter-map 9\n", 1, "version"},
      {"robuter-map 1\nwidth 0\n", 2, "bad width"},
      {"robuter-map 1\ncolour red\n", 2, "unknown header key"},
      {"robuter-map 1\nwidth 2\nheight 2\n", 3, "no 'data'"},
      {"robuter-map 1\nwidth 2\nheight 2\ndata\n....\n", 4, "must come before"},
      {head + "....\n..\n", 9, "expected 4"},
      {head + "....\n..zz\n", 9, "bad cell"},
      {head + "....\n....\nxx\n", 10, "after the map rows"},
      {head + "....\n", 8, "missing map rows"},
  };
  for (const Case& c : cases) {
    const auto r = parse_map(c.text, "m.map");
    ASSERT_FALSE(r.ok()) << c.text;
    EXPECT_EQ(r.error().line, c.line) << c.text << " -> " << r.error().text();
    EXPECT_NE(r.error().message.find(c.words), std::string::npos) << r.error().text();
  }
}

// Every loader reports a broken file as a value and touches nothing: a planner working on the
// lab keeps its map, its layers and its plan while broken environment, saved-map and parameter
// files are offered to it (robuter-plan and any caller load first, adopt only on success).
TEST(Loaders, ABrokenFileChangesNothing) {
  auto env = load_environment(std::string(PLANNER_TEST_DATA) + "/lab.env");
  ASSERT_TRUE(env.ok());
  OccupancyMap lab(MapGeometry{300, 300, 0.05, {}});
  rasterise_polygons(lab, *env);
  PlannerConfig cfg;
  cfg.radius = 0.30;
  Planner planner(cfg);
  planner.set_map(lab);
  const Pose2 start{3.0, 3.0, 0.0};
  const Point2 goal{5.0, 12.5};
  const PlanResult before = planner.plan(start, goal);
  ASSERT_TRUE(before.found());
  const std::vector<Waypoint> path_before = planner.waypoints();
  const std::string head = "robuter-map 1\nwidth 2\nheight 2\nresolution 0.05\norigin 0 0\nthreshold 10\ndata\n";
  const std::string bad_env = test::temp_file("bad.env", "2\n3\n0 0\n1 0\n");          // too few vertices
  const std::string bad_map = test::temp_file("bad.map", head + "....\n..zz\n");         // bad cell
  const std::string bad_params = test::temp_file("bad.params", "0.3\n0.2\n0\n1 1\n"); // no goal
  auto e = load_environment(bad_env);
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error().file, bad_env);
  EXPECT_GT(e.error().line, 0);
  auto m = load_map(bad_map);
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.error().text(), bad_map + ":9: bad cell 'zz' at column 1");
  auto p = load_parameters(bad_params);
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().file, bad_params);
  const robuter::test::MissingPaths paths;
  auto missing = load_map(paths.missing("robuter.map"));
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().text().find(paths.missing("robuter.map")), std::string::npos);
  // Nothing changed: the map cell by cell, no change logged, the same plan.
  ASSERT_EQ(planner.map().cell_count(), lab.cell_count());
  for (int y = 0; y < 300; ++y)
    for (int x = 0; x < 300; ++x) ASSERT_EQ(planner.map().count({x, y}), lab.count({x, y}));
  EXPECT_TRUE(planner.map().changes().empty());
  const PlanResult after = planner.plan(start, goal);
  EXPECT_EQ(after.status, before.status);
  EXPECT_DOUBLE_EQ(after.length, before.length);
  ASSERT_EQ(planner.waypoints().size(), path_before.size());
  for (std::size_t i = 0; i < path_before.size(); ++i) EXPECT_EQ(planner.waypoints()[i].cell, path_before[i].cell);
}

}  // namespace
}  // namespace robuter::plan
