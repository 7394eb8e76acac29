// SPDX-License-Identifier: GPL-3.0-or-later
// The envelope is not a toy: XG through the 90 cm door of worlds/default.toml, the ultrasonic detection on.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "tests/safety_sim/support.hpp"

namespace robuter::test::safety_sim {
namespace {

// The planner's map over the 8 × 6 m world, odometry in the world's frame (as the planner's tests).
Config door_config() {
  Config cfg;
  cfg.planner.map_origin_x_mm = -500;
  cfg.planner.map_origin_y_mm = -500;
  cfg.planner.map_width_mm = 9'000;
  cfg.planner.map_height_mm = 7'000;
  return cfg;
}

// From the west room (1.5, 1.5) to the goal (6.4, 4.6) in the east room: the only way is the
// door (100 mm each side of the body when centred). The planner is an automatic source: a
// protective stop pauses it and it goes on once its envelope is clear; nothing trips.
// Quarantined (run with --gtest_also_run_disabled_tests): measured, the planner reports
// `unreachable` after 40 s without crossing — no trip, no protective stop, no contact, closest
// 418 mm — and the same with the seed's rule (ROBUTER_EMERGENCY_RULE=seed: unreachable after
// 33 s, closest 415 mm): the planner without a prior map does not find the door in this world;
// the envelope holds nothing it needs (issue #16's a-priori map; docs/SAFETY.md §13).
// ROBUTER_PLANNER_MAP_FILE=FILE gives the planner an a-priori map ([planner] map_file): with the
// default world's map on this test's 9 x 7 m cells (robuter-plan's map cropped), measured: the
// first plan is already `unreachable` for this goal (1.0 s, closest 500 mm), though the same
// walls rasterised on PlannerSimDoor's grid give 6.40 m: the faces lie on cell boundaries and the
// tool's map rounds them into the neighbouring cells (935 cells differ; docs/PLANNER.md).
// With the default window and goal (5.6, 3.0) instead (2026-12-02, docs/SAFETY.md §13 "What the
// envelope does not do"): the plan goes through the door, the robot reaches it, and the envelope
// holds it there — echo arcs from the jamb corners leave evidence inside the opening that no cone
// can contradict from the blind near field.
TEST(EnvelopeDoor, DISABLED_XgThroughThe90cmDoorWithTheUltrasonicDetectionOnArrivesWithoutATrip) {
  Config dc = door_config();
  if (const char* r = std::getenv("ROBUTER_EMERGENCY_RULE")) dc.emergency.rule = r;
  if (const char* m = std::getenv("ROBUTER_PLANNER_MAP_FILE")) dc.planner.map_file = m;  // an a-priori map
  SimFirmware fw(ROBUTER_SHIPPED_WORLDS "/default.toml", dc);
  ASSERT_TRUE(fw.ok()) << fw.error();
  SafetyMonitor mon;
  mon.attach(fw);
  ASSERT_EQ(fw.ask("AC 15000 15000 0"), "ack");
  fw.run_ticks(5);
  ASSERT_EQ(fw.ask("XG 64000 46000"), "ack");
  const auto& robot = fw.sim().robot();
  bool crossed = false;
  PlannerState state = PlannerState::idle;
  const double t0 = fw.seconds();
  for (int i = 0; i < 60'000; ++i) {
    fw.step();
    crossed = crossed || robot.pose().x > 4.6;
    state = fw.bb().planner_status.reader().peek().state;
    if (i > 50 && (state == PlannerState::reached || state == PlannerState::unreachable ||
                   state == PlannerState::stopped || state == PlannerState::blocked)) break;
  }
  const EmergencyState& e = fw.bb().emergency.reader().peek();
  const double err = std::hypot(robot.pose().x - 6.4, robot.pose().y - 4.6);
  std::printf("door: planner state %d after %.1f s, crossed %d, final error %.3f m, trips %u, protective stops %u, "
              "closest approach %.0f mm, contacts %llu\n",
              static_cast<int>(state), fw.seconds() - t0, crossed, err, e.trips, e.protective_stops,
              mon.min_clearance_us_on * 1000.0, static_cast<unsigned long long>(mon.contact_us_on));
  EXPECT_EQ(state, PlannerState::reached);
  EXPECT_TRUE(crossed) << "through the door";
  EXPECT_EQ(e.trips, 0u);
  EXPECT_TRUE(e.envelope);
  EXPECT_EQ(e.enabled & 2u, 2u) << "the ultrasonic detection stayed on";
  EXPECT_EQ(mon.violations(), 0u) << mon.first_violation;
  RecordProperty("door_protective_stops", static_cast<int>(e.protective_stops));
}

}  // namespace
}  // namespace robuter::test::safety_sim
