// SPDX-License-Identifier: GPL-3.0-or-later
// The door-crossing steering rules (seed doors()) on hand-made scans.
#include <gtest/gtest.h>

#include "modules/doors/steering.hpp"

namespace robuter::doors {
namespace {

SectorValues all(std::int32_t v) {
  SectorValues s;
  s.fill(v);
  return s;
}

const MinReadTable kMin = min_read_table(body_geometry(robot::kRobuter));

TEST(Steering, ClearMeansStraightAtTwoCentimetresPerSecond) {
  const SideThreats t = side_threats(all(2000), kMin);
  EXPECT_FALSE(t.left);
  EXPECT_FALSE(t.right);
  EXPECT_EQ(steer(t), Steer::straight);
  const Wheels w = wheels_for(steer(t));
  EXPECT_EQ(w.left, 2);
  EXPECT_EQ(w.right, 2);
}

// 700 < 783 at 25° on the left: turn right by backing the right wheel.
TEST(Steering, LeftTooCloseTurnsRight) {
  SectorValues r = all(2000);
  r[5] = 700;
  const SideThreats t = side_threats(r, kMin);
  EXPECT_TRUE(t.left);
  EXPECT_FALSE(t.right);
  EXPECT_EQ(steer(t), Steer::turn_right);
  const Wheels w = wheels_for(Steer::turn_right);
  EXPECT_EQ(w.left, 0);
  EXPECT_EQ(w.right, -1);
}

// 380 < 386 at 300° on the right: turn left by backing the left wheel.
TEST(Steering, RightTooCloseTurnsLeft) {
  SectorValues r = all(2000);
  r[60] = 380;
  EXPECT_EQ(steer(side_threats(r, kMin)), Steer::turn_left);
  const Wheels w = wheels_for(Steer::turn_left);
  EXPECT_EQ(w.left, -1);
  EXPECT_EQ(w.right, 0);
  r[60] = 387;  // at the boundary and beyond: clear
  EXPECT_EQ(steer(side_threats(r, kMin)), Steer::straight);
}

TEST(Steering, BothSidesStop) {
  SectorValues r = all(2000);
  r[17] = 300;
  r[54] = 300;
  EXPECT_EQ(steer(side_threats(r, kMin)), Steer::stop);
  const Wheels w = wheels_for(Steer::stop);
  EXPECT_EQ(w.left, 0);
  EXPECT_EQ(w.right, 0);
}

// The seed looks at 1..17 and 54..70 only; readings < 0 are "none".
TEST(Steering, SectorsOutsideTheSidesAndMissingReadingsAreIgnored) {
  SectorValues r = all(2000);
  r[0] = 100;
  r[18] = 100;
  r[71] = 100;
  r[36] = 10;
  r[3] = -1;
  EXPECT_EQ(steer(side_threats(r, kMin)), Steer::straight);
}

TEST(Steering, CrossedWhenOneWholeSideIsBeyondMaxDist) {
  SectorValues r = all(2000);
  for (int i = 54; i <= 71; ++i) r[static_cast<std::size_t>(i)] = 400;
  EXPECT_TRUE(all_clear_on_a_side(r, 1500));   // the left is clear
  r[18] = 1499;
  EXPECT_FALSE(all_clear_on_a_side(r, 1500));  // 90° on the left counts for the end test
  for (int i = 54; i <= 71; ++i) r[static_cast<std::size_t>(i)] = 1500;
  EXPECT_TRUE(all_clear_on_a_side(r, 1500));   // the right is clear (≥ MAX_DIST)
  r[71] = -1;
  EXPECT_FALSE(all_clear_on_a_side(r, 1500));  // no reading is never clear
  r[0] = 10;  // straight ahead is not part of either side
}

}  // namespace
}  // namespace robuter::doors
