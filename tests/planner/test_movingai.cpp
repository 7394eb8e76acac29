// SPDX-License-Identifier: GPL-3.0-or-later
// Tests on the MovingAI benchmark: file parsing, and optimal lengths equal the published ones.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>

#include "modules/planner/lib/cspace.hpp"
#include "modules/planner/lib/grid_search.hpp"
#include "modules/planner/lib/movingai.hpp"

namespace robuter::plan {
namespace {

const char* const kMaps[] = {"arena", "den101d", "den312d", "lak303d", "Berlin_0_256"};

TEST(MovingAiFiles, MapParsingHandlesCrlfAndPassableLetters) {
  const auto m = parse_movingai_map("type octile\r\nheight 2\r\nwidth 4\r\nmap\r\n.GS@\r\nTW.O\r\n", "x.map");
  ASSERT_TRUE(m.ok()) << m.error().text();
  EXPECT_EQ(m->width(), 4);
  EXPECT_EQ(m->height(), 2);
  EXPECT_EQ(m->state({0, 0}), CellState::Free);
  EXPECT_EQ(m->state({1, 0}), CellState::Free);
  EXPECT_EQ(m->state({2, 0}), CellState::Free);
  EXPECT_EQ(m->state({3, 0}), CellState::Occupied);
  EXPECT_EQ(m->state({0, 1}), CellState::Occupied);
  EXPECT_EQ(m->state({1, 1}), CellState::Occupied);
  EXPECT_EQ(m->state({2, 1}), CellState::Free);
}

TEST(MovingAiFiles, MalformedMapsGiveClearErrors) {
  struct Case {
    const char* text;
    int line;
    const char* words;
  };
  const Case cases[] = {
      {"type hex\nheight 1\nwidth 1\nmap\n.\n", 1, "unsupported map type"},
      {"type octile\nheight x\nwidth 1\nmap\n.\n", 2, "bad height"},
      {"type octile\nheight 1\nwidth 1\n", 3, "no 'map' line"},
      {"type octile\nheight 2\nwidth 3\nmap\n...\n..\n", 6, "expected 3"},
      {"type octile\nheight 2\nwidth 3\nmap\n...\n", 5, "unexpected end of file"},
      {"type octile\nheight 1\nwidth 1\nmap\n.\n.\n", 6, "after the map rows"},
      {"type octile\nsize 1\nmap\n", 2, "unknown header key"},
      {"type octile\nheight 5000\nwidth 5000\nmap\n", 4, "too large"},
  };
  for (const Case& c : cases) {
    const auto r = parse_movingai_map(c.text, "bad.map");
    ASSERT_FALSE(r.ok()) << c.text;
    EXPECT_EQ(r.error().file, "bad.map");
    EXPECT_EQ(r.error().line, c.line) << r.error().text();
    EXPECT_NE(r.error().message.find(c.words), std::string::npos) << r.error().text();
  }
}

TEST(MovingAiFiles, ScenarioParsing) {
  const auto s = parse_movingai_scen("version 1\n0\tmaps/dao/a.map\t49\t49\t1\t11\t1\t12\t1\n\n", "a.scen");
  ASSERT_TRUE(s.ok()) << s.error().text();
  ASSERT_EQ(s->size(), 1u);
  EXPECT_EQ((*s)[0].start, (Cell{1, 11}));
  EXPECT_EQ((*s)[0].goal, (Cell{1, 12}));
  EXPECT_EQ((*s)[0].optimal, 1.0);
  const auto bad = parse_movingai_scen("version 1\n0\ta.map\t49\t49\t1\t11\t1\t12\n", "a.scen");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().line, 2);
  EXPECT_NE(bad.error().message.find("9 fields"), std::string::npos);
  const auto nover = parse_movingai_scen("0\ta.map\t49\t49\t1\t11\t1\t12\t1\n", "a.scen");
  ASSERT_FALSE(nover.ok());
  EXPECT_EQ(nover.error().line, 1);
  const auto num = parse_movingai_scen("version 1\n0\ta.map\t49\t49\t1\tq\t1\t12\t1\n", "a.scen");
  ASSERT_FALSE(num.ok());
  EXPECT_NE(num.error().message.find("start y"), std::string::npos);
}

// Why: answers every `stride`-th scenario of every map; returns how many were checked.
int check_maps(int stride, SearchMode mode, GridSearch::Engine engine = GridSearch::Engine::Auto) {
  int checked = 0;
  for (const char* name : kMaps) {
    const std::string dir = ROBUTER_MOVINGAI_DIR;
    const auto map = load_movingai_map(dir + "/" + name + ".map");
    const auto scen = load_movingai_scen(dir + "/" + name + ".map.scen");
    EXPECT_TRUE(map.ok() && scen.ok()) << name;
    if (!map.ok() || !scen.ok()) continue;
    PassGrid grid;
    pass_grid_from_map(*map, grid);
    GridSearch search(grid.width, grid.height);
    search.set_engine(engine);
    for (std::size_t i = 0; i < scen->size(); i += static_cast<std::size_t>(stride)) {
      const Scenario& s = (*scen)[i];
      const PlanResult r = search.find(grid, s.start, s.goal, mode);
      EXPECT_TRUE(r.found()) << name << " #" << i;
      if (mode == SearchMode::Optimal)
        EXPECT_NEAR(r.length, s.optimal, 1e-3) << name << " #" << i;
      else
        EXPECT_GE(r.length, s.optimal - 1e-3) << name << " #" << i;
      ++checked;
    }
  }
  return checked;
}

TEST(MovingAi, OptimalLengthsOnASubsetOfEveryMap) {
  EXPECT_GT(check_maps(23, SearchMode::Optimal), 100);  // jump points on these maps
  EXPECT_GT(check_maps(31, SearchMode::Optimal, GridSearch::Engine::Buckets), 80);
  EXPECT_GT(check_maps(61, SearchMode::Optimal, GridSearch::Engine::Heap), 40);
}

TEST(MovingAi, BfsPathsAreValidAndNeverShorter) {
  EXPECT_GT(check_maps(97, SearchMode::Bfs), 20);
}

// The whole set: all 2,690 scenarios of the five maps (under a second in the normal build).
TEST(MovingAi, OptimalLengthsOnEveryScenario) {
  EXPECT_EQ(check_maps(1, SearchMode::Optimal), 2690);
  EXPECT_EQ(check_maps(1, SearchMode::Optimal, GridSearch::Engine::Buckets), 2690);
}

// The maze, random and room families (512 x 512, hog2's maps/mazes, random, rooms): a sample of
// each map's scenarios, every engine. Published lengths there have 6 significant digits (hog2
// rounds sqrt 2), so a length is exact within half a unit of the 6th digit.
TEST(MovingAi, SampleOfTheMazeRandomAndRoomFamiliesEveryEngine) {
  const char* const maps[] = {"maze512-1-0", "random512-10-0", "random512-40-0", "8room_000"};
  const GridSearch::Engine engines[] = {GridSearch::Engine::Auto, GridSearch::Engine::JumpPoints,
                                        GridSearch::Engine::Buckets, GridSearch::Engine::Heap};
  int checked = 0;
  for (const char* name : maps) {
    const std::string dir = ROBUTER_MOVINGAI_DIR;
    const auto map = load_movingai_map(dir + "/" + name + ".map");
    const auto scen = load_movingai_scen(dir + "/" + name + ".map.scen");
    ASSERT_TRUE(map.ok() && scen.ok()) << name;
    PassGrid grid;
    pass_grid_from_map(*map, grid);
    GridSearch search(grid.width, grid.height);
    // Three scenarios spread over the file (it is sorted by length bucket), the longest last.
    const std::size_t n = scen->size();
    for (const std::size_t i : {n / 8, n / 2, n - 1}) {
      const Scenario& s = (*scen)[i];
      const double tolerance = std::max(1e-3, 0.5 * std::pow(10.0, std::floor(std::log10(s.optimal)) - 5.0) + 1e-6);
      for (const GridSearch::Engine engine : engines) {
        search.set_engine(engine);
        const PlanResult r = search.find(grid, s.start, s.goal, SearchMode::Optimal);
        ASSERT_TRUE(r.found()) << name << " #" << i;
        EXPECT_NEAR(r.length, s.optimal, tolerance) << name << " #" << i << " engine " << static_cast<int>(engine);
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 4 * 3 * 4);
}

// Auto's rule (measured by robuter-plan-bench, docs/PLANNER.md "Bench"): jump points on the
// game, city, maze and room maps; the bucket A* on the random grids.
TEST(MovingAi, AutoPicksTheFasterEnginePerFamily) {
  const std::pair<const char*, bool> cases[] = {
      {"arena", true},        {"den101d", true},         {"den312d", true},          {"lak303d", true},
      {"Berlin_0_256", true}, {"maze512-1-0", true},     {"8room_000", true},        {"random512-10-0", false},
      {"random512-40-0", false}};
  for (const auto& [name, jump] : cases) {
    const auto map = load_movingai_map(std::string(ROBUTER_MOVINGAI_DIR) + "/" + name + ".map");
    ASSERT_TRUE(map.ok()) << name;
    PassGrid grid;
    pass_grid_from_map(*map, grid);
    GridSearch search(grid.width, grid.height);
    EXPECT_EQ(search.prefers_jump_points(grid), jump)
        << name << ": scattered " << search.scattered_fraction(grid) << ", runs " << search.run_fraction(grid);
  }
}

TEST(MovingAi, GoalOutsideTheMap) {
  const auto map = parse_movingai_map("type octile\nheight 2\nwidth 2\nmap\n..\n..\n", "m.map");
  ASSERT_TRUE(map.ok());
  PassGrid grid;
  pass_grid_from_map(*map, grid);
  GridSearch search(2, 2);
  EXPECT_EQ(search.find(grid, {0, 0}, {5, 1}, SearchMode::Optimal).status, PlanStatus::GoalOutside);
  EXPECT_EQ(search.find(grid, {0, 0}, {1, 1}, SearchMode::Optimal).status, PlanStatus::Found);
}

}  // namespace
}  // namespace robuter::plan
