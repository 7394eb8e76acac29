// SPDX-License-Identifier: GPL-3.0-or-later
// The project's TOML world format: contents, units, doors, and each error kind with its line.
#include <gtest/gtest.h>

#include <cmath>

#include "hal/sim/world_io.hpp"

namespace robuter::sim {
namespace {

constexpr const char* kRoom = R"(# a test room
[world]
name = "room"
units = "m"

[start]
x = 1.0
y = 1.0
heading_deg = 90

[[wall]]
name = "walls"
points = [[0, 0], [5, 0], [5, 4], [0, 4]]
closed = true
)";

// Expects a parse error at `line` whose message contains `fragment`.
void expect_world_error(const std::string& text, int line, const std::string& fragment) {
  const auto r = parse_world_toml(text, "room.toml");
  ASSERT_FALSE(r.ok()) << "parsed but should fail:\n" << text;
  EXPECT_EQ(r.error().file, "room.toml");
  EXPECT_EQ(r.error().line, line) << r.error().describe();
  EXPECT_NE(r.error().message.find(fragment), std::string::npos) << r.error().describe();
}

TEST(TomlWorld, LoadsARoom) {
  const auto r = parse_world_toml(kRoom, "room.toml");
  ASSERT_TRUE(r.ok()) << r.error().describe();
  const World& w = r.value();
  EXPECT_EQ(w.name, "room");
  ASSERT_TRUE(w.start.has_value());
  EXPECT_DOUBLE_EQ(w.start->theta, kPi / 2);
  EXPECT_EQ(w.start_line, 6);
  EXPECT_EQ(w.obstacles().size(), 4u);
  // Wall centre lines on the rectangle, 10 cm thick, squared-off ends.
  EXPECT_NEAR(w.bounds().lo.x(), -0.05, 1e-12);
  EXPECT_NEAR(w.bounds().hi.y(), 4.05, 1e-12);
}

TEST(TomlWorld, ObjectsDoorsMarkersAndUnits) {
  const std::string text = std::string(kRoom) + R"(
[goal]
x = 3.75
y = 3.25

[[wall]]
name = "partition"
from = [2.5, 0]
to = [2.5, 4]
thickness = 0.2
doors = [{ name = "d1", at = 1.0, width = 0.9 }, { at = 3.0, width = 0.8 }]

[[box]]
name = "crate"
center = [4, 1]
size = [0.5, 0.3]
angle_deg = 90

[[rectangle]]
min = [3.5, 3.0]
max = [4.0, 3.5]

[[polygon]]
name = "tri"
points = [[1, 3], [2, 3], [1.5, 3.5], [1, 3]]

[[marker]]
name = "door front"
x = 2.0
y = 1.0
heading_deg = 0
)";
  auto r = parse_world_toml(text, "room.toml");
  ASSERT_FALSE(r.ok());  // the goal is inside the rectangle: fix it and retry
  EXPECT_EQ(r.error().line, 16);
  EXPECT_NE(r.error().message.find("goal is inside obstacle 'rectangle 1'"), std::string::npos);
  std::string fixed = text;
  fixed.replace(fixed.find("y = 3.25"), 8, "y = 2.00");
  r = parse_world_toml(fixed, "room.toml");
  ASSERT_TRUE(r.ok()) << r.error().describe();
  const World& w = r.value();
  ASSERT_EQ(w.doors.size(), 2u);
  EXPECT_EQ(w.doors[0].name, "d1");
  EXPECT_EQ(w.doors[1].name, "partition door 2");
  EXPECT_NEAR(w.doors[0].centre.y(), 1.0, 1e-12);
  EXPECT_NEAR(w.doors[0].width, 0.9, 1e-12);
  // 4 outer walls + partition in 3 pieces + box + rectangle + triangle.
  EXPECT_EQ(w.obstacles().size(), 4u + 3u + 3u);
  ASSERT_EQ(w.markers.size(), 1u);
  EXPECT_EQ(w.markers[0].name, "door front");
  // The partition's first piece ends exactly at the door jamb: y = 1.0 - 0.45.
  double top = -1.0;
  for (const auto& v : w.obstacles()[4].vertices) top = std::max(top, v.y());
  EXPECT_NEAR(top, 0.55, 1e-12);
  // The rotated box spans 0.3 along x and 0.5 along y.
  double x0 = 1e9, x1 = -1e9;
  for (const auto& v : w.obstacles()[7].vertices) {
    x0 = std::min(x0, v.x());
    x1 = std::max(x1, v.x());
  }
  EXPECT_NEAR(x1 - x0, 0.3, 1e-12);
}

TEST(TomlWorld, CentimetresAndMillimetres) {
  const auto r = parse_world_toml(R"([world]
units = "cm"
wall_thickness = 10
[start]
x = 100
y = 100
[[wall]]
points = [[0, 0], [500, 0], [500, 400], [0, 400]]
closed = true
)",
                                  "cm.toml");
  ASSERT_TRUE(r.ok()) << r.error().describe();
  EXPECT_DOUBLE_EQ(r.value().start->x, 1.0);
  EXPECT_NEAR(r.value().bounds().hi.x(), 5.05, 1e-12);
  expect_world_error("[world]\nunits = \"ft\"\n[start]\nx = 1\ny = 1\n", 2, "units: expected");
}

TEST(TomlWorld, UnknownKeys) {
  expect_world_error(std::string(kRoom) + "colour = \"red\"\n", 15, "[[wall]] 'walls': unknown key 'colour'");
  expect_world_error("[start]\nx = 1\ny = 1\nz = 0\n", 4, "[start]: unknown key 'z'");
  expect_world_error("[start]\nx = 1\ny = 1\n[robot]\nlength = 1\n", 4, "unknown key 'robot'");
  expect_world_error("[start]\nx = 1\ny = 1\n[[box]]\ncenter = [3, 3]\nsize = [1, 1]\nheight = 2\n", 7,
               "[[box]] 'box 1': unknown key 'height'");
  expect_world_error("[start]\nx = 1\ny = 1\n[[wall]]\nfrom = [3, 3]\nto = [4, 3]\n"
               "doors = [{ at = 0.5, width = 0.2, swing = 90 }]\n",
               7, "unknown key 'swing'");
}

TEST(TomlWorld, NonNumbers) {
  expect_world_error("[start]\nx = \"one\"\ny = 1\n", 2, "[start]: x: expected a number, found a string");
  expect_world_error("[start]\nx = 1\ny = 1\n[[box]]\ncenter = [3, \"3\"]\nsize = [1, 1]\n", 5,
               "center: expected a number");
  expect_world_error("[start]\nx = 1\ny = 1\n[[box]]\ncenter = [3, 3, 3]\nsize = [1, 1]\n", 5,
               "expected a point [x, y], found an array of 3 values");
  expect_world_error("[start]\nx = 1\ny = 1\n[[wall]]\nfrom = [3, 3]\nto = [4, 3]\nthickness = true\n", 7,
               "thickness: expected a number, found a boolean");
}

TEST(TomlWorld, UnclosedPolygonsAndBadCounts) {
  expect_world_error("[start]\nx = 1\ny = 1\n[[polygon]]\nname = \"p\"\npoints = [[3, 3], [4, 3], [4, 4]]\n",
               6, "bad count: a polygon needs at least 3 corners");
  expect_world_error("[start]\nx = 1\ny = 1\n[[polygon]]\nname = \"p\"\n"
               "points = [[3, 3], [4, 3], [4, 4], [3, 4]]\n",
               6, "[[polygon]] 'p': polygon is not closed");
  expect_world_error("[start]\nx = 1\ny = 1\n[[polygon]]\npoints = [[3, 3], [4, 3], [5, 3], [3, 3]]\n", 5,
               "no area");
  expect_world_error("[start]\nx = 1\ny = 1\n[[wall]]\npoints = [[3, 3]]\n", 5, "at least 2 points");
}

TEST(TomlWorld, StartPoseInsideAWall) {
  // The body (0.695 ahead, 0.330 behind, 0.35 each side) reaches the wall at x = 1.5.
  expect_world_error("[start]\nx = 1.0\ny = 1\n[[wall]]\nname = \"w\"\nfrom = [1.6, 0]\nto = [1.6, 3]\n", 1,
               "start pose is inside a wall: the robot's body there overlaps obstacle 'w' (line 4)");
  // Entirely inside a big box.
  expect_world_error("# comment\n[start]\nx = 1.0\ny = 1\n[[box]]\nname = \"big\"\ncenter = [1, 1]\n"
               "size = [4, 4]\n",
               2, "start pose is inside obstacle 'big'");
  // Just clear of it is fine.
  EXPECT_TRUE(parse_world_toml("[start]\nx = 0.8\ny = 1\n[[wall]]\nfrom = [1.6, 0]\nto = [1.6, 3]\n",
                               "ok.toml")
                  .ok());
}

TEST(TomlWorld, MissingAndMisplacedTables) {
  expect_world_error("[[wall]]\nfrom = [0, 0]\nto = [1, 0]\n", 1, "missing [start]");
  expect_world_error("[start]\nx = 1\n", 1, "[start]: missing key 'y'");
  expect_world_error("[start]\nx = 1\ny = 1\n[wall]\nfrom = [3, 0]\nto = [4, 0]\n", 4, "must be written [[wall]]");
  expect_world_error("[[start]]\nx = 1\ny = 1\n", 1, "must be a table [start]");
}

TEST(TomlWorld, DoorsMustFitAndNotOverlap) {
  const std::string head = "[start]\nx = 1\ny = 1\n[[wall]]\nname = \"w\"\nfrom = [3, 0]\nto = [3, 4]\n";
  expect_world_error(head + "doors = [{ at = 0.2, width = 0.9 }]\n", 8, "does not fit in its wall");
  expect_world_error(head + "doors = [\n  { name = \"a\", at = 1.0, width = 0.9 },\n"
                      "  { name = \"b\", at = 1.5, width = 0.9 },\n]\n",
               10, "doors 'a' and 'b' overlap");
  expect_world_error(head + "doors = [{ at = 1.0, width = 0 }]\n", 8, "width: must be positive");
  expect_world_error("[start]\nx = 1\ny = 1\n[[wall]]\npoints = [[3, 0], [3, 4]]\n"
               "doors = [{ at = 1.0, width = 0.9 }]\n",
               6, "only a straight wall");
}

TEST(TomlWorld, DuplicateNames) {
  expect_world_error("[start]\nx = 1\ny = 1\n[[box]]\nname = \"a\"\ncenter = [3, 3]\nsize = [1, 1]\n"
               "[[box]]\nname = \"a\"\ncenter = [5, 3]\nsize = [1, 1]\n",
               8, "duplicate name 'a' (first used on line 4)");
}

TEST(TomlWorld, SyntaxErrorsCarryTheirLine) {
  const auto r = parse_world_toml("[start]\nx = 1\ny = = 1\n", "bad.toml");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().file, "bad.toml");
  EXPECT_EQ(r.error().line, 3);
}

}  // namespace
}  // namespace robuter::sim
