// SPDX-License-Identifier: GPL-3.0-or-later
// The planner's map window: its rule (map_bounds.hpp), a goal too far refused, a move keeping the evidence.
#include <gtest/gtest.h>

#include <cstdio>

#include "modules/planner/map_bounds.hpp"
#include "tests/planner_sim/nav_harness.hpp"

namespace robuter {
namespace {

// Why: the rule's figures for the default configuration: a 16 m window of 5 cm cells, a margin
// of the body's reach (778 mm) + one cell; the thesis lab's goal moves the window by whole cells
// to be centred between the robot and the goal; 15 m apart does not fit.
TEST(PlannerWindow, TheRuleCentresTheWindowOnWholeCellsAndNeedsTheMargin) {
  const Config cfg;
  const planner::MapWindow now = planner::configured_window(cfg.planner);
  EXPECT_EQ(now.x0, -80'000);
  EXPECT_EQ(now.w, 160'000);
  EXPECT_EQ(planner::window_margin(cfg.planner, robot_model(cfg)), 8'290);  // 779 mm (rounded up) + 0 + 50 mm
  // Seed 000: robot at (2.5, 2.0) m, goal (15.0, 5.5) m: off the default window.
  EXPECT_FALSE(planner::on_window(now, 150'000, 55'000));
  const auto s = planner::window_shift(cfg.planner, robot_model(cfg), now, 25'000, 20'000, 150'000, 55'000);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->dx, 175);  // corner (0.75, -4.25) m: centred on (8.75, 3.75) m
  EXPECT_EQ(s->dy, 75);
  EXPECT_TRUE(planner::goal_acceptable(cfg.planner, robot_model(cfg), now, 25'000, 20'000, 150'000, 55'000));
  // 14.3 m apart fits (0.85 m each side); 15 m does not; a goal on the window needs no move.
  EXPECT_TRUE(planner::window_shift(cfg.planner, robot_model(cfg), now, 0, 0, 0, 143'000));
  EXPECT_FALSE(planner::window_shift(cfg.planner, robot_model(cfg), now, 0, 0, 0, 150'000));
  EXPECT_FALSE(planner::goal_acceptable(cfg.planner, robot_model(cfg), now, 0, 0, 0, 150'000));
  EXPECT_TRUE(planner::goal_acceptable(cfg.planner, robot_model(cfg), now, 0, 0, 79'999, 0));
}

// Why: a goal no window of the configured size holds with the robot is refused (error 4) and
// changes nothing: the goal being served goes on, the window stays where it was.
TEST(PlannerWindow, AGoalTooFarForTheWindowIsRefusedAndNothingChanges) {
  test::SimFirmware fw;  // default world and configuration, the robot at the odometry origin
  ASSERT_TRUE(fw.ok()) << fw.error();
  ASSERT_EQ(fw.ask("XB1"), "ack");  // verbose errors
  PlannerModule* pm = test::planner_of(fw);
  ASSERT_NE(pm, nullptr);
  ASSERT_EQ(fw.ask("XG 5000 0"), "ack");
  fw.run_ticks(20);
  const auto before = fw.ask("XP");
  ASSERT_TRUE(before);
  ASSERT_EQ(before->rfind("P ", 0), 0u);
  EXPECT_NE(before->find(" 5000 0 "), std::string::npos) << *before;
  EXPECT_EQ(fw.ask("XG 0 150000"), "error 4 out-of-range");
  EXPECT_EQ(fw.ask("XG -160000 0"), "error 4 out-of-range");
  fw.run_ticks(5);
  EXPECT_EQ(pm->map_x0_mm(), -8000);
  EXPECT_EQ(pm->map_y0_mm(), -8000);
  const auto after = fw.ask("XP");
  ASSERT_TRUE(after);
  EXPECT_NE(after->find(" 5000 0 "), std::string::npos) << *after;  // still the first goal
  EXPECT_EQ(fw.bb().planner_status.reader().peek().goal_seq, 1u);
}

// Why: what the ring saw before a move stays at its odometry coordinates: every cell of the old
// map that the new window covers keeps its count, the rest of the new window is unknown; the
// layers are then rebuilt over several activations (XP reads scanning), and the run goes on.
TEST(PlannerWindow, AMoveKeepsTheEvidenceSeenBeforeAtItsOdometryCoordinates) {
  test::SimFirmware fw(ROBUTER_WORLDS_DIR "/seed000_lab.toml");
  ASSERT_TRUE(fw.ok()) << fw.error();
  PlannerModule* pm = test::planner_of(fw);
  ASSERT_NE(pm, nullptr);
  ASSERT_EQ(fw.ask("AC 25000 20000 0"), "ack");
  fw.run_ticks(5);
  ASSERT_EQ(fw.ask("XG 75000 15000"), "ack");  // 5 m east, on the default window: sees benches, wall
  const test::NavRecord near = test::run_navigation(fw, 20'000, 7.5, 1.5, "near");
  ASSERT_EQ(near.state, PlannerState::reached);
  const plan::OccupancyMap& map = pm->planner().map();
  plan::OccupancyMap old = map;
  const std::int64_t x0 = pm->map_x0_mm();
  fw.send_raw("XG 150000 55000\r");
  int ticks = 0;
  for (; ticks < 200 && pm->map_x0_mm() == x0; ++ticks) {
    old = map;  // the map of the activation before the move (the move's own activation marks first)
    fw.step();
  }
  ASSERT_NE(pm->map_x0_mm(), x0) << "the window did not move";
  // Centred between the robot (about (7.5, 1.5) m) and the goal: corner about (3.25, -4.5) m.
  EXPECT_NEAR(static_cast<double>(pm->map_x0_mm()), 3250.0, 100.0);
  EXPECT_NEAR(static_cast<double>(pm->map_y0_mm()), -4500.0, 100.0);
  EXPECT_EQ((pm->map_x0_mm() - x0) % 50, 0);  // whole cells
  EXPECT_TRUE(pm->planner().rebuilding());
  // The move's activation marked the readings of that tick before moving: compare states of
  // cells the ring did not touch then (the robot is at rest: the same few beams), and counts.
  int kept = 0, differ = 0, unknown_new = 0;
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x) {
      const plan::Point2 c = map.center({x, y});
      const plan::Cell o = old.cell_of(c);
      if (!old.contains(o)) {
        EXPECT_EQ(map.state({x, y}), plan::CellState::Unknown);
        ++unknown_new;
        continue;
      }
      if (old.state(o) == plan::CellState::Occupied) {
        ++kept;
        if (map.state({x, y}) != plan::CellState::Occupied) ++differ;
      }
    }
  std::printf("window move: %d obstacle cells of the overlap, %d changed state, %d new cells unknown\n", kept,
              differ, unknown_new);
  EXPECT_GT(kept, 20);
  EXPECT_LE(differ, 2);  // at most what one activation's beams could flip
  EXPECT_GT(unknown_new, 0);
  // XP reads scanning while the layers are rebuilt, then the navigation goes on.
  fw.count_lines();  // the XG's ack
  const auto xp = fw.ask("XP");
  ASSERT_TRUE(xp);
  EXPECT_EQ(xp->rfind("P scanning 150000 55000 ", 0), 0u) << *xp;
  fw.run_ticks(300);  // 65 layers, 3 per activation of every 10 ticks
  EXPECT_FALSE(pm->planner().rebuilding());
}

// Why: an a-priori map ([planner] map_file) fixes the map's geometry: a goal off it is refused
// even where an unknown map's window would move to hold it, and nothing changes.
TEST(PlannerWindow, WithAnAPrioriMapFileAGoalOffTheMapIsRefused) {
  Config cfg;
  cfg.planner.map_file = PLANNER_SIM_DATA "/default_world.map";  // (-0.6, -0.55) m, 183 x 142 cells
  test::SimFirmware fw(ROBUTER_WORLDS_DIR "/default.toml", cfg);
  ASSERT_TRUE(fw.ok()) << fw.error();
  PlannerModule* pm = test::planner_of(fw);
  ASSERT_NE(pm, nullptr);
  ASSERT_EQ(fw.ask("XB1"), "ack");
  ASSERT_EQ(fw.ask("AC 15000 15000 0"), "ack");
  fw.run_ticks(5);
  // (1.5, 6.8) m lies 0.25 m north of the map; without the file a window of its size would
  // move to hold the robot and it (0.9 m to spare).
  Config file = cfg;  // the geometry the file gives the planner
  file.planner.map_origin_x_mm = -600;
  file.planner.map_origin_y_mm = -550;
  file.planner.map_width_mm = 183 * 50;
  file.planner.map_height_mm = 142 * 50;
  Config unknown = file;
  unknown.planner.map_file.clear();
  const planner::MapWindow now = planner::configured_window(file.planner);
  EXPECT_TRUE(planner::window_shift(unknown.planner, robot_model(unknown), now, 15'000, 15'000, 15'000, 68'000));
  EXPECT_FALSE(planner::goal_acceptable(file.planner, robot_model(file), now, 15'000, 15'000, 15'000, 68'000));
  EXPECT_EQ(fw.ask("XG 15000 68000"), "error 4 out-of-range");
  fw.run_ticks(20);
  EXPECT_EQ(pm->state(), PlannerState::idle);
  EXPECT_EQ(pm->map_x0_mm(), -600);
  EXPECT_EQ(pm->map_y0_mm(), -550);
  EXPECT_EQ(fw.ask("XG 15000 60000"), "ack");  // on the map: taken
}

}  // namespace
}  // namespace robuter
