// SPDX-License-Identifier: GPL-3.0-or-later
// (b) The 90 cm door of worlds/default.toml at plan level, on the known map: the Robuter's
// rectangle (the firmware's default planner) passes, the disc of the thesis' method does not.
#include <gtest/gtest.h>

#include "hal/sim/world_io.hpp"
#include "modules/planner/lib/bresenham.hpp"
#include "modules/planner/planner_settings.hpp"

namespace robuter {
namespace {

// Every obstacle edge of the world rasterised into a map of the planner's default cells.
plan::OccupancyMap known_map(const sim::World& world, const planner::PlannerSettings& s) {
  plan::OccupancyMap map(s.map, s.hit_threshold);
  for (const sim::Segment& e : world.segments()) {
    const plan::Cell a = map.cell_of(plan::Point2{e.a.x(), e.a.y()});
    const plan::Cell b = map.cell_of(plan::Point2{e.b.x(), e.b.y()});
    plan::for_each_line_cell(a, b, [&](int x, int y) {
      if (map.contains({x, y})) map.mark_occupied({x, y});
      return true;
    });
  }
  return map;
}

Config world_config() {
  Config cfg;  // the defaults, on a map that covers the 8 x 6 m world
  cfg.planner.map_origin_x_mm = -500;
  cfg.planner.map_origin_y_mm = -500;
  cfg.planner.map_width_mm = 9'000;
  cfg.planner.map_height_mm = 7'000;
  return cfg;
}

TEST(PlannerSimDoor, RectanglePlansThroughThe90cmDoorDiscReportsNoPath) {
  auto loaded = sim::load_world(ROBUTER_WORLDS_DIR "/default.toml");
  ASSERT_TRUE(loaded.ok());
  const sim::World& world = loaded.value();
  ASSERT_EQ(world.doors.size(), 1u);
  const sim::Door& door = world.doors[0];
  ASSERT_NEAR(door.width, 0.90, 1e-9);
  const plan::Pose2 start{world.start->x, world.start->y, world.start->theta};
  const plan::Point2 goal{world.goal->x(), world.goal->y()};

  Config cfg = world_config();
  const planner::PlannerSettings rect = planner::make_settings(cfg.planner, robot_model(cfg), cfg.ptu.cap_mm);
  ASSERT_EQ(rect.planner.footprint, plan::FootprintKind::Rectangle);
  plan::Planner p(rect.planner);
  p.set_map(known_map(world, rect));
  const plan::PlanResult r = p.plan(start, goal);
  ASSERT_TRUE(r.found()) << plan::to_string(r.status);
  // The path crosses the partition (x = 4.5 m) within the door's opening.
  bool through = false;
  const auto& w = p.waypoints();
  for (std::size_t i = 1; i < w.size(); ++i) {
    if ((w[i - 1].pose.x - 4.5) * (w[i].pose.x - 4.5) <= 0.0 && w[i - 1].pose.x != w[i].pose.x) {
      EXPECT_NEAR(w[i].pose.y, door.centre.y(), 0.45) << "crossed outside the door";
      through = true;
    }
  }
  EXPECT_TRUE(through);
  std::printf("rectangle through the %.2f m door: %.2f m, %zu waypoints, %u states expanded\n", door.width,
              r.length * rect.map.resolution, w.size(), r.expanded);

  cfg.planner.footprint = "disc";  // the thesis' method: the body as the disc it sweeps turning
  const planner::PlannerSettings disc = planner::make_settings(cfg.planner, robot_model(cfg), cfg.ptu.cap_mm);
  plan::Planner q(disc.planner);
  q.set_map(known_map(world, disc));
  const plan::PlanResult d = q.plan(start, goal);
  EXPECT_FALSE(d.found()) << "a " << disc.planner.radius << " m disc passed a 90 cm door";
  // A goal in the east room where the disc fits: no path, because of the door alone.
  const plan::Point2 open_goal{5.6, 3.0};
  const plan::PlanResult d2 = q.plan(start, open_goal);
  EXPECT_EQ(d2.status, plan::PlanStatus::Unreachable);
  EXPECT_TRUE(p.plan(start, open_goal).found());
  std::printf("disc of %.3f m: %s (world goal), %s (%.1f, %.1f)\n", disc.planner.radius,
              std::string(plan::to_string(d.status)).c_str(), std::string(plan::to_string(d2.status)).c_str(),
              open_goal.x, open_goal.y);
}

}  // namespace
}  // namespace robuter
