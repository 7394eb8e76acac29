// SPDX-License-Identifier: GPL-3.0-or-later
// Range correction, spike filter and differences: hand-computed values from seed ptu.c.
#include <gtest/gtest.h>

#include "modules/ptu/scan_filter.hpp"

namespace robuter::ptu {
namespace {

// real = (measured − 46) / 0.96, truncated; capped at 2491 first; no echo counts as the cap.
TEST(RangeCorrection, SeedCalibrationLine) {
  EXPECT_EQ(correct_range(2491), 2546);  // 2445 / 0.96 = 2546.875
  EXPECT_EQ(correct_range(3000), 2546);  // above the time-out range: the cap
  EXPECT_EQ(correct_range(0), 2546);     // no echo: the cap
  EXPECT_EQ(correct_range(1006), 1000);  // 960 / 0.96
  EXPECT_EQ(correct_range(1000), 993);   // 954 / 0.96 = 993.75
  EXPECT_EQ(correct_range(500), 472);    // 454 / 0.96 = 472.9
  EXPECT_EQ(correct_range(46), 0);
  EXPECT_EQ(correct_range(30), 0);       // never negative
}

// Why (issue #22): the seed's two numbers. Its `read_pt()` corrects with offset 46 (kept here),
// its text fits Y = 0.96 X + 43 (what the simulator's transducer follows, docs/DOORS.md PT-2):
// a wall 1.000 m from the face reads 0.96 * 1000 + 43 = 1003 raw, which the firmware reports as
// 996 (3.1 mm short, before truncation); the text's own line would report 1000. The seed's table
// shows a no-echo sector as 2491, the raw cap: its code, like ours, reports 2546 (PT-1).
TEST(RangeCorrection, TheSeedsCodeAgainstItsTextAndTable) {
  EXPECT_EQ(correct_range(1003), 996);   // the simulated wall at 1.000 m, through the seed's code
  RangeCalibration text;
  text.offset_mm = 43;
  EXPECT_EQ(correct_range(1003, text), 1000);  // the text's line: exact
  EXPECT_EQ(correct_range(2491, text), 2550);  // and the cap: 15 ms of sound at 340 m/s, 2.550 m
  EXPECT_EQ(correct_range(0), 2546);     // the table's "2491" is the raw cap, not what P sends
}

TEST(RangeCorrection, OtherCalibration) {
  RangeCalibration c;
  c.cap_mm = 5000;
  c.offset_mm = 0;
  c.scale_permille = 1000;
  EXPECT_EQ(correct_range(1234, c), 1234);
  EXPECT_EQ(correct_range(0, c), 5000);
}

SectorValues all(std::int32_t v) {
  SectorValues s;
  s.fill(v);
  return s;
}

// A low value between two above MAX (2300) and under MAX − 1000 becomes their mean.
TEST(SpikeFilter, IsolatedLowBetweenTwoHighsIsReplacedByTheirMean) {
  SectorValues raw = all(2500);
  raw[9] = 2400;
  raw[10] = 800;
  raw[11] = 2600;
  SectorValues f;
  spike_filter(raw, f);
  EXPECT_EQ(f[10], 2500);  // (2400 + 2600) / 2
  EXPECT_EQ(f[9], 2400);
  EXPECT_EQ(f[11], 2600);
}

TEST(SpikeFilter, KeepsEverythingElse) {
  SectorValues raw = all(2500);
  raw[20] = 1500;                 // not under 1300: not a spike
  raw[30] = 2400, raw[31] = 700, raw[32] = 2000;  // a neighbour not above 2300
  raw[40] = 800, raw[41] = 800;   // two lows side by side
  raw[50] = 2300, raw[51] = 500, raw[52] = 2500;  // 2300 is not above MAX
  SectorValues f;
  spike_filter(raw, f);
  EXPECT_EQ(f[20], 1500);
  EXPECT_EQ(f[31], 700);
  EXPECT_EQ(f[40], 800);
  EXPECT_EQ(f[41], 800);
  EXPECT_EQ(f[51], 500);
}

// Sectors 71 and 0 are neighbours (the seed's two special cases).
TEST(SpikeFilter, WrapsAroundTheCircle) {
  SectorValues raw = all(2500);
  raw[71] = 2400;
  raw[0] = 500;
  raw[1] = 2600;
  SectorValues f;
  spike_filter(raw, f);
  EXPECT_EQ(f[0], 2500);   // (pt[71] + pt[1]) / 2
  EXPECT_EQ(f[71], 2400);  // its neighbour pt[0] = 500 is not high
  raw = all(2500);
  raw[70] = 2400;
  raw[71] = 300;
  raw[0] = 2700;
  spike_filter(raw, f);
  EXPECT_EQ(f[71], 2550);  // (pt[70] + pt[0]) / 2
}

TEST(Differences, AdjacentDifferencesWrapAtTheEnd) {
  SectorValues f;
  for (int i = 0; i < kSectors; ++i) f[static_cast<std::size_t>(i)] = 1000 + 10 * i;
  f[5] = 2500;
  SectorValues d;
  differences(f, d);
  EXPECT_EQ(d[0], 10);
  EXPECT_EQ(d[4], 2500 - 1040);
  EXPECT_EQ(d[5], 1060 - 2500);
  EXPECT_EQ(d[71], 1000 - 1710);  // f[0] − f[71]
}

}  // namespace
}  // namespace robuter::ptu
