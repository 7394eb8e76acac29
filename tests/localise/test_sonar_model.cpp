// SPDX-License-Identifier: GPL-3.0-or-later
// The sonar model against a corridor of known walls: which echoes the map promises, what a
// silence says, and which walls can explain an echo (issue #18, docs/LOCALISATION.md).
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "modules/localise/lib/distance_field.hpp"
#include "modules/localise/lib/sonar_likelihood.hpp"

namespace robuter::loc {
namespace {

// 12 × 6 m at 5 cm: a corridor 2.2 m wide (free from y = 1.1 to 3.3) between two walls 0.1 m
// thick, a 1 m door in the north wall (x 6..7), the corridor closed by a wall at x = 11.
DistanceField corridor() {
  FieldGeometry g;
  g.width = 240;
  g.height = 120;
  g.resolution = 0.05;
  std::vector<std::uint8_t> occ(static_cast<std::size_t>(g.width * g.height), 0);
  const auto wall = [&](double x0, double y0, double x1, double y1) {
    for (int y = 0; y < g.height; ++y)
      for (int x = 0; x < g.width; ++x) {
        const double cx = (x + 0.5) * g.resolution, cy = (y + 0.5) * g.resolution;
        if (cx >= x0 && cx < x1 && cy >= y0 && cy < y1) occ[static_cast<std::size_t>(y * g.width + x)] = 1;
      }
  };
  wall(0.0, 1.0, 11.1, 1.1);   // south
  wall(0.0, 3.3, 6.0, 3.4);    // north, west of the door
  wall(7.0, 3.3, 11.1, 3.4);   // north, east of the door
  wall(11.0, 1.0, 11.1, 3.4);  // the corridor's end
  return DistanceField(g, occ, 2.0);
}

const Eigen::Vector2d kNorth(0.0, 1.0), kEast(1.0, 0.0);

TEST(SonarModel, TheFieldsNormalPointsAwayFromTheNearestWallAndIsFlatWhereNoneIsWithinReach) {
  const DistanceField f = corridor();
  Eigen::Vector2d n;
  ASSERT_TRUE(f.normal({3.0, 1.5}, n));  // 0.4 m north of the south wall
  EXPECT_NEAR(n.y(), 1.0, 0.01);
  ASSERT_TRUE(f.normal({3.0, 0.6}, n));  // south of it
  EXPECT_NEAR(n.y(), -1.0, 0.01);
  ASSERT_TRUE(f.normal({10.6, 2.2}, n));  // before the end wall
  EXPECT_NEAR(n.x(), -1.0, 0.01);
  EXPECT_FALSE(f.normal({3.0, 5.9}, n));  // 2.5 m north of the corridor: past the field's 2 m cap
  EXPECT_FALSE(f.normal({-1.0, 2.2}, n)); // off the grid
}

TEST(SonarModel, AWallMetHeadOnIsPromisedAndOneOnlyGrazedIsNot) {
  const DistanceField f = corridor();
  const SonarModelParams p;
  const ArcTable cone = cone_table(p);
  EXPECT_TRUE(promises_echo(f, {3.0, 2.2}, kNorth, 4.6, p, cone));   // the north wall 1.1 m ahead
  EXPECT_FALSE(promises_echo(f, {3.0, 2.2}, kNorth, 0.8, p, cone));  // but not within 0.8 m
  EXPECT_TRUE(promises_echo(f, {8.0, 2.2}, kEast, 4.6, p, cone));    // the end wall 3 m ahead
  // Along the corridor, the end wall 8 m off: the side walls cross the cone only at grazing
  // incidence (77.5°), which returns nothing.
  EXPECT_FALSE(promises_echo(f, {3.0, 2.2}, kEast, 4.6, p, cone));
  EXPECT_FALSE(promises_echo(f, {3.0, 1.6}, kEast, 4.6, p, cone));   // nor 0.5 m from one of them
  // Through the door: nothing on the other side of it within reach.
  EXPECT_FALSE(promises_echo(f, {6.5, 2.2}, kNorth, 4.6, p, cone));
  // A wall nearer than the blanking distance blinds the sensor: no echo to promise.
  EXPECT_FALSE(promises_echo(f, {3.0, 3.2}, kNorth, 4.6, p, cone));
}

// Why: a ring that hears nothing where the map has a wall head-on is evidence against the pose —
// the only evidence along a corridor whose walls are the same for 13 m (the kidnapped robot);
// but only within the firing's reach: a firing shortened while moving (3 m) says nothing of a wall
// beyond it, and counting those silences lost the robot at the floor's first crossing.
TEST(SonarModel, ASilenceTellsAgainstAPoseOnlyWhereTheMapPromisesAnEchoWithinTheFiringsReach) {
  const DistanceField f = corridor();
  const SonarModelParams p;
  const ArcTable cone = cone_table(p);
  EXPECT_DOUBLE_EQ(silence_likelihood(f, {3.0, 2.2}, kNorth, 4.95, p, cone), p.miss_weight);
  EXPECT_DOUBLE_EQ(silence_likelihood(f, {3.0, 2.2}, kNorth, 1.0, p, cone), 1.0);   // beyond the reach
  EXPECT_DOUBLE_EQ(silence_likelihood(f, {3.0, 2.2}, kEast, 4.95, p, cone), 1.0);   // along the corridor
  EXPECT_DOUBLE_EQ(silence_likelihood(f, {6.5, 2.2}, kNorth, 4.95, p, cone), 1.0);  // through the door
}

// Why: the arc of an echo 2.3 m long from a sensor 0.5 m off a corridor's wall, looking along it,
// touches the wall at its cone's edge; the old model took that as the echo's surface (a wall met at
// 77.5° from its normal, which returns nothing), so a pose 2.5 m along the corridor explained the
// far echoes of a crossing as well as the true one did (the kidnapped robot went unnoticed).
TEST(SonarModel, AnEchoIsNotExplainedByAWallTheBeamOnlyGrazes) {
  const DistanceField f = corridor();
  const SonarModelParams p;
  const ArcTable arc = arc_table(p);
  const double grazed = arc_likelihood(f, {3.0, 1.6}, kEast, 2.31, p, arc);
  const double head_on = arc_likelihood(f, {8.0, 2.2}, kEast, 3.0, p, arc);
  EXPECT_GT(head_on, 0.9);
  EXPECT_LT(grazed, p.z_rand + 0.05);
}

// An echo from beyond a wall the map promises would have echoed first is unlikely; one from the
// wall itself is not.
TEST(SonarModel, AnEchoFromBeyondAPromisedWallCarriesTheThroughWeight) {
  const DistanceField f = corridor();
  const SonarModelParams p;
  const ArcTable arc = arc_table(p), cone = cone_table(p);
  const double at_wall = sonar_likelihood(f, {3.0, 2.2}, kNorth, 1.1, p, arc, cone);
  const double beyond = sonar_likelihood(f, {3.0, 2.2}, kNorth, 2.2, p, arc, cone);
  EXPECT_GT(at_wall, 0.9);
  EXPECT_LE(beyond, p.through_weight);
}

}  // namespace
}  // namespace robuter::loc
