// SPDX-License-Identifier: GPL-3.0-or-later
// Minimum admissible readings per sector from the robot's geometry (seed init_doors), by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "modules/doors/min_read.hpp"

namespace robuter::doors {
namespace {

// x1 = 725 − 50 + 35, x2 = 1025 − 725 − 50 + 35, x3 = 350 − 50 + 35, x4 = 700 − 350 − 50 + 35.
TEST(MinRead, SideDistancesOfTheSeedRobot) {
  const SideDistances s = side_distances(body_geometry(robot::kRobuter));
  EXPECT_EQ(s.front, 710);
  EXPECT_EQ(s.rear, 285);
  EXPECT_EQ(s.left, 335);
  EXPECT_EQ(s.right, 335);
}

TEST(MinRead, TableValuesWorkedOutByHand) {
  const MinReadTable t = min_read_table(body_geometry(robot::kRobuter));
  EXPECT_EQ(t[0], 710);
  EXPECT_EQ(t[1], 712);   // 710 / cos 5° = 712.7
  EXPECT_EQ(t[5], 783);   // 710 / cos 25° = 783.4
  EXPECT_EQ(t[6], 670);   // 335 / sin 30°
  EXPECT_EQ(t[9], 473);   // 335 / sin 45° = 473.8
  EXPECT_EQ(t[18], 335);  // 335 / sin 90°
  EXPECT_EQ(t[19], 336);  // 335 / sin 85° = 336.3
  EXPECT_EQ(t[27], 473);  // 335 / sin 45°
  EXPECT_EQ(t[28], 372);  // 285 / cos 40° = 372.0
  EXPECT_EQ(t[35], 286);  // 285 / cos 5° = 286.1
  EXPECT_EQ(t[36], 285);
  EXPECT_EQ(t[37], 286);
  EXPECT_EQ(t[45], 403);  // 285 / cos 45° = 403.1
  EXPECT_EQ(t[46], 437);  // 335 / sin 50° = 437.3
  EXPECT_EQ(t[54], 335);
  EXPECT_EQ(t[55], 336);
  EXPECT_EQ(t[60], 386);  // 335 / sin 60° = 386.8
  EXPECT_EQ(t[66], 670);
  EXPECT_EQ(t[67], 783);
  EXPECT_EQ(t[71], 712);
}

// Front half mirror-symmetric for a centred pan-tilt; the seed's rear is not (its left rear uses
// x3/sin up to 135°, its right rear x2/cos down to 225°).
TEST(MinRead, FrontHalfSymmetricRearAsTheSeedWroteIt) {
  const MinReadTable t = min_read_table(body_geometry(robot::kRobuter));
  for (int i = 1; i <= 18; ++i) EXPECT_EQ(t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>(72 - i)]) << i;
  EXPECT_EQ(t[27], 473);  // 335 / sin 45°
  EXPECT_EQ(t[45], 403);  // 285 / cos 45°
}

// The continuous boundary agrees with the table on the sectors the crossing checks.
TEST(MinRead, ContinuousBoundaryMatchesTheTableWhereTheCrossingLooks) {
  const BodyGeometry g = body_geometry(robot::kRobuter);
  const MinReadTable t = min_read_table(g);
  const SideDistances s = side_distances(g);
  for (int i : {1, 2, 3, 4, 5, 6, 10, 17, 18, 54, 60, 66, 67, 70, 71}) {
    const double a = i * 5.0 * std::numbers::pi / 180.0;
    EXPECT_NEAR(min_read_at(s, a), t[static_cast<std::size_t>(i)], 1.0) << i;  // the table truncates
  }
  EXPECT_NEAR(min_read_at(s, 40.0 * std::numbers::pi / 180.0), 335.0 / std::sin(40.0 * std::numbers::pi / 180.0),
              1e-9);
  EXPECT_NEAR(min_read_at(s, std::numbers::pi), 285.0, 1e-9);
}

}  // namespace
}  // namespace robuter::doors
