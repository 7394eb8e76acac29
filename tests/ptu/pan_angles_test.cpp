// SPDX-License-Identifier: GPL-3.0-or-later
// Pan positions to degrees and sectors: values worked out by hand from seed ptu.c (read_pt).
#include <gtest/gtest.h>

#include "modules/ptu/pan_angles.hpp"

namespace robuter::ptu {
namespace {

// angle = pos·185/3600 with C's truncation towards zero.
TEST(PanAngles, PositionToDegreesTruncatesLikeC) {
  EXPECT_EQ(position_to_degrees(-1755), -90);  // −324675/3600 = −90.19
  EXPECT_EQ(position_to_degrees(1655), 85);    // 306175/3600 = 85.05
  EXPECT_EQ(position_to_degrees(100), 5);      // 18500/3600 = 5.14
  EXPECT_EQ(position_to_degrees(97), 4);       // 17945/3600 = 4.98
  EXPECT_EQ(position_to_degrees(-20), -1);     // −3700/3600 = −1.03
  EXPECT_EQ(position_to_degrees(0), 0);
}

// Multiples of 5 and their ±1° neighbours land on (angle + 90)/5; the rest fire nothing.
TEST(PanAngles, SectorWithinOneDegreeOfAMultipleOfFive) {
  EXPECT_EQ(sector_of_degrees(-90), 0);
  EXPECT_EQ(sector_of_degrees(-89), 0);   // ends in 9, negative: one down to −90
  EXPECT_EQ(sector_of_degrees(-91), 0);   // ends in 1, negative: one up to −90
  EXPECT_EQ(sector_of_degrees(0), 18);
  EXPECT_EQ(sector_of_degrees(1), 18);
  EXPECT_EQ(sector_of_degrees(-1), 18);
  EXPECT_EQ(sector_of_degrees(4), 19);
  EXPECT_EQ(sector_of_degrees(5), 19);
  EXPECT_EQ(sector_of_degrees(6), 19);
  EXPECT_EQ(sector_of_degrees(-4), 17);
  EXPECT_EQ(sector_of_degrees(-6), 17);
  EXPECT_EQ(sector_of_degrees(11), 20);
  EXPECT_EQ(sector_of_degrees(14), 21);
  EXPECT_EQ(sector_of_degrees(16), 21);
  EXPECT_EQ(sector_of_degrees(85), 35);
  EXPECT_EQ(sector_of_degrees(86), 35);
}

TEST(PanAngles, NoSectorAwayFromMultiplesOrOutsideTheSweep) {
  for (int a : {2, 3, 7, 8, -2, -3, -7, -8, -88, 42, 83})
    EXPECT_EQ(sector_of_degrees(a), -1) << a;
  EXPECT_EQ(sector_of_degrees(89), -1);   // rounds to 90: beyond the sweep (85)
  EXPECT_EQ(sector_of_degrees(90), -1);
  EXPECT_EQ(sector_of_degrees(-95), -1);
}

// Every 5° sector of a whole sweep gets filled, each transducer covering one half.
TEST(PanAngles, ASweepCoversAllSeventyTwoSectors) {
  bool seen[kSectors] = {};
  for (int pos = -1755; pos <= 1655; ++pos) {
    const int s = sector_of_degrees(position_to_degrees(pos));
    if (s < 0) continue;
    seen[s] = true;
    seen[opposite_sector(s)] = true;
  }
  for (int i = 0; i < kSectors; ++i) EXPECT_TRUE(seen[i]) << i;
}

// The firing rule: nearest multiple of 5 within the tolerance, by hand.
TEST(PanAngles, SectorNearAMultipleOfFive) {
  EXPECT_NEAR(position_to_angle(-1755), -90.1875, 1e-9);
  EXPECT_NEAR(position_to_angle(1655), 85.0486, 1e-4);
  EXPECT_EQ(sector_near(-90.1875, 1.5), 0);
  EXPECT_EQ(sector_near(-71.4, 1.5), 4);   // −70 ± 1.5
  EXPECT_EQ(sector_near(-71.6, 1.5), -1);
  EXPECT_EQ(sector_near(1.49, 1.5), 18);
  EXPECT_EQ(sector_near(3.6, 1.5), 19);
  EXPECT_EQ(sector_near(3.4, 1.5), -1);
  EXPECT_EQ(sector_near(85.0486, 1.5), 35);
  EXPECT_EQ(sector_near(88.6, 1.5), -1);   // nearest is 90: beyond the sweep
  EXPECT_EQ(sector_near(-91.0, 1.5), 0);
  EXPECT_EQ(sector_near(4.0, 1.0), 19);
  EXPECT_EQ(sector_near(3.9, 1.0), -1);
}

TEST(PanAngles, WrapSector) {
  EXPECT_EQ(wrap_sector(72), 0);
  EXPECT_EQ(wrap_sector(-1), 71);
  EXPECT_EQ(wrap_sector(145), 1);
  EXPECT_EQ(opposite_sector(35), 71);
}

}  // namespace
}  // namespace robuter::ptu
