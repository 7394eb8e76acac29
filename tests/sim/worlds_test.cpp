// SPDX-License-Identifier: GPL-3.0-or-later
// The shipped worlds: all load, and each has the geometry it promises.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "hal/sim/robot.hpp"
#include "hal/sim/sonar_layout.hpp"
#include "hal/sim/world_io.hpp"
#include "tests/sim/sim_test_util.hpp"

namespace robuter::sim {
namespace {

// Loads a shipped world, failing the test (and returning an empty world) on error.
World load(const std::string& name) {
  auto r = load_world(test::world_path(name));
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().describe());
  return r.ok() ? std::move(r).value() : World{};
}

// The marker of that name, or null.
const Marker* marker(const World& w, const std::string& name) {
  for (const auto& m : w.markers) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

TEST(ShippedWorlds, APlaceGraphBesideItsWorldIsNotAWorld) {
  EXPECT_TRUE(is_world_file("worlds/building_floor.toml"));
  EXPECT_TRUE(is_world_file("seed000_lab.env"));
  EXPECT_FALSE(is_world_file("worlds/building_floor.places.toml"));
  EXPECT_FALSE(is_world_file("notes.txt"));
}

TEST(ShippedWorlds, AllLoad) {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(ROBUTER_WORLDS_DIR)) {
    const auto ext = e.path().extension();
    if (!is_world_file(e.path())) continue;
    SCOPED_TRACE(e.path().string());
    auto r = load_world(e.path());
    ASSERT_TRUE(r.ok()) << r.error().describe();
    EXPECT_FALSE(r.value().obstacles().empty());
    if (ext == ".toml") {
      EXPECT_TRUE(r.value().start.has_value());
    }
    names.insert(e.path().filename().string());
  }
  for (const char* n : {"default.toml", "empty.toml", "seed002_course.toml", "seed000_lab.toml",
                        "seed000_lab.env", "door90.toml", "door100.toml", "gap70.toml", "building_floor.toml"}) {
    EXPECT_TRUE(names.count(n)) << n;
  }
}

// About 8 × 6 m, two rooms joined by one 90 cm door, start and goal in different rooms.
TEST(ShippedWorlds, DefaultLab) {
  const World w = load("default.toml");
  EXPECT_NEAR(w.bounds().hi.x() - w.bounds().lo.x(), 8.1, 1e-9);
  EXPECT_NEAR(w.bounds().hi.y() - w.bounds().lo.y(), 6.1, 1e-9);
  ASSERT_EQ(w.doors.size(), 1u);
  EXPECT_NEAR(w.doors[0].width, 0.90, 1e-12);
  ASSERT_TRUE(w.goal.has_value());
  EXPECT_LT(w.start->x, w.doors[0].centre.x());
  EXPECT_GT(w.goal->x(), w.doors[0].centre.x());
}

TEST(ShippedWorlds, EmptyArenaHasOnlyWalls) {
  const World w = load("empty.toml");
  EXPECT_EQ(w.obstacles().size(), 4u);
  EXPECT_TRUE(w.doors.empty());
}

// One opening of the stated width; the axle 1.5 m from the wall's near face, facing it.
TEST(ShippedWorlds, DoorWorlds) {
  for (const auto& [file, width] : {std::pair{"door90.toml", 0.90}, std::pair{"door100.toml", 1.00},
                                    std::pair{"gap70.toml", 0.70}}) {
    SCOPED_TRACE(file);
    const World w = load(file);
    ASSERT_EQ(w.doors.size(), 1u);
    const Door& d = w.doors[0];
    EXPECT_NEAR(d.width, width, 1e-12);
    const double near_face = d.centre.y() - 0.5 * d.wall_thickness;
    EXPECT_NEAR(near_face - w.start->y, 1.5, 1e-12);
    EXPECT_NEAR(w.start->x, d.centre.x(), 1e-12);
    EXPECT_NEAR(w.start->theta, kPi / 2, 1e-12);
    ASSERT_NE(marker(w, "beyond"), nullptr);
  }
}

// The .env and the .toml describe the same polygons; the goal is 13 m from the start.
TEST(ShippedWorlds, Seed000LabBothFormatsAgree) {
  const World t = load("seed000_lab.toml");
  const World e = load("seed000_lab.env");
  EXPECT_NEAR(t.bounds().hi.x() - t.bounds().lo.x(), 18.1, 1e-9);
  EXPECT_NEAR(t.bounds().hi.y() - t.bounds().lo.y(), 10.1, 1e-9);
  ASSERT_TRUE(t.goal.has_value());
  EXPECT_NEAR(std::hypot(t.goal->x() - t.start->x, t.goal->y() - t.start->y), 13.0, 0.05);
  auto canon = [](const World& w) {
    std::vector<std::vector<std::pair<long, long>>> out;
    for (const auto& ob : w.obstacles()) {
      std::vector<std::pair<long, long>> v;
      for (const auto& p : ob.vertices) v.emplace_back(std::lround(p.x() * 1000), std::lround(p.y() * 1000));
      std::sort(v.begin(), v.end());
      out.push_back(v);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  EXPECT_EQ(canon(t), canon(e));
}

// Drives at constant wheel speeds for `seconds`, failing the test on any contact.
void drive(Robot& r, double left, double right, double seconds) {
  r.command({left, right});
  double t = 0.0;
  while (t < seconds - 1e-12) {
    const double dt = std::min(0.01, seconds - t);
    r.step(dt);
    t += dt;
    ASSERT_FALSE(r.bumper()) << "contact at " << r.pose().x << ", " << r.pose().y;
  }
}

// Seed 002's calibration geometry: at the calibration stop sensors 17 and 19 both read DISTY
// = 1 m and sensor 1 reads DISTX = 1.2 m; the loop (west 2.5 m, half-circle right R = 1 m, east
// 2.5 m, half-circle right) is collision-free and closes on the recalibration point.
TEST(ShippedWorlds, Seed002CourseCalibrationGeometry) {
  const World w = load("seed002_course.toml");
  const Marker* stop = marker(w, "calibration stop");
  ASSERT_NE(stop, nullptr);
  SonarModel sonar(w, default_ring_params());
  const RingLayout ring = default_ring_layout();
  EXPECT_NEAR(sonar.measure(stop->pose, ring[16]), 1.0, 1e-9);  // sensor 17
  EXPECT_NEAR(sonar.measure(stop->pose, ring[18]), 1.0, 1e-9);  // sensor 19
  EXPECT_NEAR(sonar.measure(stop->pose, ring[0]), 1.2, 1e-9);   // sensor 1

  RobotParams p;
  p.limits.max_accel = 0.0;
  p.limits.max_decel = 0.0;
  Robot robot(w, p, *w.start);
  const double v = 0.2, radius = 1.0, b = p.geometry.wheel_base;
  const double outer = v * (radius + b / 2) / radius, inner = v * (radius - b / 2) / radius;
  const double half_circle = kPi * radius / v;
  drive(robot, v, v, 2.5 / v);
  drive(robot, outer, inner, half_circle);  // right turn: the left wheel runs outside
  drive(robot, v, v, 2.5 / v);
  EXPECT_NEAR(robot.pose().x, stop->pose.x, 1e-6);
  EXPECT_NEAR(robot.pose().y, stop->pose.y, 1e-6);
  drive(robot, outer, inner, half_circle);
  EXPECT_NEAR(robot.pose().x, w.start->x, 1e-6);
  EXPECT_NEAR(robot.pose().y, w.start->y, 1e-6);
  EXPECT_NEAR(wrap_angle(robot.pose().theta - w.start->theta), 0.0, 1e-9);
}

}  // namespace
}  // namespace robuter::sim
