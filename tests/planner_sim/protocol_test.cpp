// SPDX-License-Identifier: GPL-3.0-or-later
// (c) The planner's protocol on the whole firmware: goal errors, unreachable goals, XP, XM, XH.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "tests/planner_sim/nav_harness.hpp"

namespace robuter {
namespace {

// XP without its last two fields (the longest activation and the clock, which move anyway).
std::string xp_body(const std::string& xp) {
  const auto last = xp.rfind(' ');
  return xp.substr(0, xp.rfind(' ', last - 1));
}

// The robot stands still and the planner reports what it reported before.
void expect_unchanged(test::SimFirmware& fw, const std::string& before) {
  const auto after = fw.ask("XP");
  ASSERT_TRUE(after);
  EXPECT_EQ(xp_body(*after), xp_body(before));
  const Posture& p = fw.bb().posture.reader().peek();
  EXPECT_EQ(p.left, 0);
  EXPECT_EQ(p.right, 0);
}

TEST(PlannerSimProtocol, MalformedOrOffTheMapGoalsAreErrorsAndChangeNothing) {
  test::SimFirmware fw;  // default world, default planner map (16 x 16 m around the start)
  ASSERT_TRUE(fw.ok()) << fw.error();
  ASSERT_EQ(fw.ask("XB1"), "ack");
  const auto before = fw.ask("XP");
  ASSERT_TRUE(before);
  EXPECT_EQ(before->rfind("P idle 0 0 0 0 0 0 0 0 ", 0), 0u) << *before;
  EXPECT_EQ(fw.ask("XG 900000 0"), "error 4 out-of-range");     // 90 m: off the map
  EXPECT_EQ(fw.ask("XG 0 -150000"), "error 4 out-of-range");    // 15 m: no 16 m window holds both
  EXPECT_EQ(fw.ask("XG 10000 10000 18001"), "error 4 out-of-range");  // theta
  EXPECT_EQ(fw.ask("XG 10000"), "error 2 bad-parameter-count");
  EXPECT_EQ(fw.ask("XG 1 2 3 4"), "error 2 bad-parameter-count");
  EXPECT_EQ(fw.ask("XG 1x 2"), "error 3 not-a-number");
  EXPECT_EQ(fw.ask("XP 1"), "error 2 bad-parameter-count");
  EXPECT_EQ(fw.ask("XM 1"), "error 2 bad-parameter-count");
  EXPECT_EQ(fw.ask("XH 1"), "error 2 bad-parameter-count");
  fw.run_ticks(50);
  expect_unchanged(fw, *before);
  const auto xv = fw.ask("XV");
  ASSERT_TRUE(xv);
  EXPECT_NE(xv->find(",planner"), std::string::npos) << *xv;
}

// A goal outside a closed room (on the map): the robot scans, finds the walls, and reports
// unreachable; nothing moves afterwards.
TEST(PlannerSimProtocol, GoalOutsideAClosedRoomIsReportedUnreachable) {
  Config cfg;
  cfg.planner.map_origin_x_mm = -1000;
  cfg.planner.map_origin_y_mm = -1000;
  cfg.planner.map_width_mm = 8'000;
  cfg.planner.map_height_mm = 5'000;
  test::SimFirmware fw(PLANNER_SIM_DATA "/closed_room.toml", cfg);
  ASSERT_TRUE(fw.ok()) << fw.error();
  ASSERT_EQ(fw.ask("AC 18000 12000 0"), "ack");  // odometry in the world's frame
  fw.run_ticks(5);
  ASSERT_EQ(fw.ask("XG 55000 12000"), "ack");    // 2 m east of the east wall
  const test::NavRecord r = test::run_navigation(fw, 30'000, 5.5, 1.2, "closed-room");
  std::printf("closed room: state %d after %u plans, %u scans, %.1f s simulated, %.2f m driven, min clearance "
              "%.3f m\n", static_cast<int>(r.state), r.plans, r.scans, r.seconds, r.travelled, r.min_clearance);
  EXPECT_EQ(r.state, PlannerState::unreachable);
  EXPECT_FALSE(r.bumper);
  EXPECT_EQ(r.trips, 0u);
  const auto xp = fw.ask("XP");
  ASSERT_TRUE(xp);
  EXPECT_EQ(xp->rfind("P unreachable 55000 12000 0 0 " + std::to_string(r.plans - 1) + " " +
                          std::to_string(r.scans) + " ", 0), 0u) << *xp;
  fw.run_ticks(100);
  const Posture& p = fw.bb().posture.reader().peek();
  EXPECT_EQ(p.left, 0);
  EXPECT_EQ(p.right, 0);
}

// XM: one line, 41 rows of 41 of seed 003's characters, the robot in the middle; XH stops a
// navigation at once.
TEST(PlannerSimProtocol, MapWindowAndHalt) {
  test::SimFirmware fw;
  ASSERT_TRUE(fw.ok()) << fw.error();
  fw.run_ticks(150);  // two ring passes marked
  const auto xm = fw.ask("XM");
  ASSERT_TRUE(xm);
  int w = 0, h = 0, cell = 0, x = 0, y = 0, n = 0;
  ASSERT_EQ(std::sscanf(xm->c_str(), "M %d %d %d %d %d %n", &w, &h, &cell, &x, &y, &n), 5) << *xm;
  EXPECT_EQ(w, 41);
  EXPECT_EQ(h, 41);
  EXPECT_EQ(cell, 50);
  const std::string head = "M 41 41 50 " + std::to_string(x) + " " + std::to_string(y) + " ";
  ASSERT_EQ(xm->rfind(head, 0), 0u);
  const std::string rows = xm->substr(head.size());
  ASSERT_EQ(rows.size(), 41u * 41u + 40u);
  for (std::size_t r = 0; r < 41; ++r) {
    if (r > 0) {
      EXPECT_EQ(rows[r * 42 - 1], '|');
    }
    for (std::size_t c = 0; c < 41; ++c) {
      const char ch = rows[r * 42 + c];
      EXPECT_TRUE(ch == '.' || ch == '#' || ch == ' ' || ch == 'P') << int(ch);
      EXPECT_EQ(ch == 'P', r == 20 && c == 20);
    }
  }
  EXPECT_NE(rows.find(' '), std::string::npos);  // the ring has cleared cells already
  std::printf("XM around the start of worlds/default.toml:\n");
  for (std::size_t r = 0; r < 41; ++r) std::printf("  |%s|\n", rows.substr(r * 42, 41).c_str());

  // A goal 2 m ahead; halt it while moving.
  ASSERT_EQ(fw.ask("XG 20000 0"), "ack");
  PlannerModule* pm = test::planner_of(fw);
  ASSERT_NE(pm, nullptr);
  ASSERT_TRUE(fw.run_until([&] { return pm->state() == PlannerState::moving && fw.bb().posture.reader().peek().left != 0; },
                           3000))
      << static_cast<int>(pm->state()) << " " << *fw.ask("XP");
  // A refused goal while navigating changes nothing: the same goal is served, the robot moves on.
  ASSERT_EQ(fw.ask("XB1"), "ack");
  const std::uint32_t seq = fw.bb().planner_goal.reader().generation();
  EXPECT_EQ(fw.ask("XG 900000 0"), "error 4 out-of-range");
  EXPECT_EQ(fw.ask("XG 1x 0"), "error 3 not-a-number");
  fw.run_ticks(20);
  EXPECT_EQ(fw.bb().planner_goal.reader().generation(), seq);
  const PlannerState now = pm->state();
  EXPECT_TRUE(now == PlannerState::moving || now == PlannerState::scanning || now == PlannerState::planning)
      << static_cast<int>(now);
  const auto during = fw.ask("XP");
  ASSERT_TRUE(during);
  EXPECT_EQ(during->find(" 20000 0 "), during->find(' ', 2)) << *during;  // goal unchanged
  EXPECT_EQ(fw.ask("XH"), "ack");
  fw.run_ticks(60);
  EXPECT_EQ(pm->state(), PlannerState::cancelled);
  const Posture& p = fw.bb().posture.reader().peek();
  EXPECT_EQ(p.left, 0);
  EXPECT_EQ(p.right, 0);
  const auto xp = fw.ask("XP");
  ASSERT_TRUE(xp);
  EXPECT_EQ(xp->rfind("P cancelled 20000 0 ", 0), 0u) << *xp;
}

// A plan is made in steps, one per activation (docs/PLANNER.md, "The module"): the operator's
// command, XH or a new goal in the middle of the steps drops them; the plan that follows is the
// newest goal's, and nothing of the dropped one drives the robot.
TEST(PlannerSimProtocol, APlanInStepsIsDroppedWhenTheOperatorOrANewGoalTakesOver) {
  test::SimFirmware fw;
  ASSERT_TRUE(fw.ok()) << fw.error();
  PlannerModule* pm = test::planner_of(fw);
  ASSERT_NE(pm, nullptr);
  const auto in_steps = [&] { return pm->state() == PlannerState::planning && pm->planner().stepping(); };
  const auto at_rest = [&] {
    const Posture& p = fw.bb().posture.reader().peek();
    return p.left == 0 && p.right == 0;
  };

  // The operator: AM 0 0 ends the navigation in the middle of its cost field.
  ASSERT_EQ(fw.ask("XG 20000 0"), "ack");
  ASSERT_TRUE(fw.run_until(in_steps, 3000)) << *fw.ask("XP");
  ASSERT_EQ(fw.ask("AM 0 0"), "ack");
  EXPECT_TRUE(fw.run_until([&] { return pm->state() == PlannerState::operator_ended; }, 10));  // its next activation
  EXPECT_FALSE(pm->planner().stepping());
  for (int i = 0; i < 200; ++i) {
    fw.step();
    ASSERT_TRUE(at_rest()) << "tick " << i << " after the operator's AM 0 0";
  }

  // XH in the middle of the steps: cancelled, the steps dropped.
  ASSERT_EQ(fw.ask("XG 10000 10000"), "ack");
  ASSERT_TRUE(fw.run_until(in_steps, 3000)) << *fw.ask("XP");
  ASSERT_EQ(fw.ask("XH"), "ack");
  EXPECT_TRUE(fw.run_until([&] { return pm->state() == PlannerState::cancelled; }, 10));  // its next activation
  EXPECT_FALSE(pm->planner().stepping());

  // A new goal in the middle of the steps: the plan made is the new goal's.
  ASSERT_EQ(fw.ask("XG 20000 0"), "ack");
  ASSERT_TRUE(fw.run_until(in_steps, 3000)) << *fw.ask("XP");
  ASSERT_EQ(fw.ask("XG 0 15000"), "ack");
  ASSERT_TRUE(fw.run_until([&] { return pm->state() != PlannerState::scanning && pm->state() != PlannerState::planning; },
                           3000))
      << *fw.ask("XP");
  EXPECT_EQ(pm->state(), PlannerState::moving) << *fw.ask("XP");
  const auto& path = pm->planner().waypoints();
  ASSERT_FALSE(path.empty());
  EXPECT_NEAR(path.back().pose.x, 0.0, 0.1);
  EXPECT_NEAR(path.back().pose.y, 1.5, 0.1);
  EXPECT_EQ(fw.ask("XH"), "ack");
}

}  // namespace
}  // namespace robuter
