// SPDX-License-Identifier: GPL-3.0-or-later
// Seed 000's environment-file format: what loads, and each error kind with its file and line.
#include <gtest/gtest.h>

#include "hal/sim/world_io.hpp"
#include "tests/support/missing_path.hpp"

namespace robuter::sim {
namespace {

// Expects a parse error at `line` whose message contains `fragment`.
void expect_env_error(std::string_view text, int line, const std::string& fragment) {
  const auto r = parse_world_env(text, "lab.env");
  ASSERT_FALSE(r.ok()) << "parsed but should fail: " << text;
  EXPECT_EQ(r.error().file, "lab.env");
  EXPECT_EQ(r.error().line, line) << r.error().describe();
  EXPECT_NE(r.error().message.find(fragment), std::string::npos) << r.error().describe();
  EXPECT_EQ(r.error().describe().rfind("lab.env:" + std::to_string(line) + ": ", 0), 0u);
}

TEST(EnvFormat, LoadsTheAnnexLayout) {
  const auto r = parse_world_env(
      "2\n"
      "4\n"
      "0 0\n"
      "1.5 0\n"
      "1.5 2\n"
      "0 2.0\n"
      "\n"
      "3\n"
      "3 3\n"
      "4 3\n"
      "3.5 4\n",
      "dir/room.env");
  ASSERT_TRUE(r.ok()) << r.error().describe();
  const World& w = r.value();
  EXPECT_EQ(w.name, "room");
  ASSERT_EQ(w.obstacles().size(), 2u);
  EXPECT_EQ(w.obstacles()[0].vertices.size(), 4u);
  EXPECT_EQ(w.obstacles()[1].line, 8);
  EXPECT_EQ(w.segments().size(), 7u);  // polygons close by themselves
  EXPECT_DOUBLE_EQ(w.bounds().hi.x(), 4.0);
  EXPECT_FALSE(w.start.has_value());
}

TEST(EnvFormat, EmptyFileAndZeroObstaclesAreEmptyWorlds) {
  EXPECT_TRUE(parse_world_env("", "e.env").ok());
  EXPECT_TRUE(parse_world_env("  \n\n", "e.env").ok());
  const auto r = parse_world_env("0\n", "e.env");
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.value().obstacles().empty());
}

TEST(EnvFormat, AcceptsCrlfSignsExponentsAndExplicitClosure) {
  const auto r = parse_world_env("1\r\n4\r\n+0 0\r\n1e0 0\r\n1 1\r\n0 0\r\n", "crlf.env");
  ASSERT_TRUE(r.ok()) << r.error().describe();
  EXPECT_EQ(r.value().obstacles()[0].vertices.size(), 3u);  // closing vertex dropped
}

TEST(EnvFormat, TwoVertexObstacleIsAThinWall) {
  const auto r = parse_world_env("1\n2\n0 0\n3 0\n", "wall.env");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.value().segments().size(), 1u);
}

TEST(EnvFormat, NonNumbers) {
  expect_env_error("1\n3\n0 0\n1 x\n1 1\n", 4, "expected a number for y of vertex 2 of obstacle 1");
  expect_env_error("one\n", 1, "the number of obstacles");
  expect_env_error("1\nthree\n", 2, "vertex count of obstacle 1");
  expect_env_error("1.5\n", 1, "whole number");
  expect_env_error("1\n3\n0 0\n1 nan\n1 1\n", 4, "found 'nan'");
}

TEST(EnvFormat, BadCounts) {
  // The first line promises 2 obstacles, the file holds 1.
  expect_env_error("2\n3\n0 0\n1 0\n1 1\n", 1, "declares 2 obstacles but ends after 1");
  // The vertex count promises 4, the file ends after 3.
  expect_env_error("1\n4\n0 0\n1 0\n1 1\n", 2, "declares 4 vertices but the file ends after 3");
  // The vertex count promises 3 but a 4th vertex follows (read as trailing data).
  expect_env_error("1\n3\n0 0\n1 0\n1 1\n0 1\n", 6, "unexpected data after the last of the 1");
  // The vertex count is too small to make an obstacle.
  expect_env_error("1\n1\n0 0\n", 2, "obstacle 1 has 1 vertices");
  expect_env_error("-1\n", 1, "cannot be negative");
  // Too few vertices: the next obstacle's count line is read where a vertex was expected.
  expect_env_error("2\n4\n0 0\n1 0\n1 1\n3\n2 2\n3 2\n3 3\n", 6, "single value where vertex 4");
}

TEST(EnvFormat, MalformedLines) {
  expect_env_error("1\n3\n0 0 0\n1 0\n1 1\n", 3, "expected 'x y' for vertex 1 of obstacle 1, found 3");
  expect_env_error("1 3\n", 1, "alone on the line");
  expect_env_error("1\n3\n0 0\n0 0\n0 0\n", 2, "no extent");
}

TEST(EnvFormat, MissingFileIsAnError) {
  const robuter::test::MissingPaths paths;
  const auto r = load_world(paths.missing("none.env"));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().line, 0);
  EXPECT_NE(r.error().message.find("cannot open"), std::string::npos);
}

}  // namespace
}  // namespace robuter::sim
