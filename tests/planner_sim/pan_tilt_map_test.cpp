// SPDX-License-Identifier: GPL-3.0-or-later
// The pan-tilt's scan marks the planner's map too (the ring switched off to tell them apart).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/planner_sim/nav_harness.hpp"

namespace robuter {
namespace {

struct Counts {
  int occupied = 0;  // cells
  int free = 0;      // cells
  int wall = 0;      // occupied cells 1.3-1.9 m ahead of the start (the door's wall), cells
};

Counts count(const plan::OccupancyMap& map) {
  Counts c;
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x) {
      const plan::CellState s = map.state({x, y});
      if (s == plan::CellState::Occupied) {
        ++c.occupied;
        const plan::Point2 p = map.center({x, y});
        if (p.x > 1.3 && p.x < 1.9 && std::abs(p.y) < 1.5) ++c.wall;
      }
      if (s == plan::CellState::Free) ++c.free;
    }
  return c;
}

// worlds/door90.toml: the robot 1.5 m from a wall with a 90 cm door. No ring ("us" not in the
// table): before Ap only the body's cells are known; after two sweeps the wall is on the map.
TEST(PlannerSimPanTilt, ThePanTiltScanMarksTheMap) {
  Config cfg;
  cfg.enabled_modules = std::vector<std::string>{"sim", "serial", "executor", "emergency", "heartbeat", "planner", "ptu"};
  test::SimFirmware fw(ROBUTER_WORLDS_DIR "/door90.toml", cfg, {}, true);
  ASSERT_TRUE(fw.ok()) << fw.error();
  PlannerModule* pm = test::planner_of(fw);
  ASSERT_NE(pm, nullptr);
  fw.run_ticks(300);
  const Counts before = count(pm->planner().map());
  EXPECT_EQ(before.occupied, 0);
  ASSERT_EQ(fw.ask("Ap"), "ack");
  ASSERT_TRUE(fw.run_until([&] { return fw.bb().pan_tilt_scan.reader().peek().sweeps >= 3; }, 3000));
  fw.run_ticks(20);  // the planner's next activation
  const Counts after = count(pm->planner().map());
  std::printf("pan-tilt only: %d occupied, %d free cells (before: %d, %d); %d on the wall ahead\n", after.occupied,
              after.free, before.occupied, before.free, after.wall);
  EXPECT_GT(after.occupied, 10);
  EXPECT_GT(after.free, before.free + 500);
  EXPECT_GE(after.wall, 5);  // 6 before the arc rule looked half a cell beyond the arc (5 since)
}

}  // namespace
}  // namespace robuter
