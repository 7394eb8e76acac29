// SPDX-License-Identifier: GPL-3.0-or-later
// Test support: run a navigation of the whole firmware and record what happened on the way.
#pragma once

#include <cstdint>
#include <string>
#include <string>

#include "modules/firmware/sim_firmware.hpp"
#include "modules/planner/planner_module.hpp"

namespace robuter::test {

// What a navigation run did.
struct NavRecord {
  PlannerState state = PlannerState::idle;  // final state
  std::uint32_t plans = 0;      // plans made (first + replans)
  std::uint32_t scans = 0;      // stops to scan
  std::uint32_t run_us_max = 0; // longest planner activation, µs (wall clock)
  double seconds = 0.0;         // simulated time of the navigation, s
  double travelled = 0.0;       // axle path length, m
  double min_clearance = 1e9;   // smallest body-to-obstacle distance seen, m (true pose)
  bool bumper = false;          // the bumper was pressed at some tick
  std::uint32_t trips = 0;      // emergencies during the run
  double final_error = 0.0;     // axle to goal at the end, m (world frame)
  int pictures = 0;             // pictures the firmware wrote (--planner-pictures), count
  std::string plan_times;       // every plan's time, µs, space-separated
  std::uint32_t whole_fields = 0;  // cost fields computed whole in one activation (the module makes them in steps: 0)
};

// The planner module of a running firmware (null if its row is absent).
PlannerModule* planner_of(SimFirmware& fw);

// Why: smallest distance from the robot's true body to any obstacle edge of the world, m.
double body_clearance(SimFirmware& fw);

// Why: steps the firmware until the planner leaves its navigating states or `max_ticks` pass,
// checking the bumper every tick and the clearance every 10 ticks. Goal in world metres for
// final_error; `label` names the run for the caller. Pictures are the firmware's own
// (SimFirmware's planner_pictures).
NavRecord run_navigation(SimFirmware& fw, int max_ticks, double goal_x, double goal_y, const std::string& label);

}  // namespace robuter::test
