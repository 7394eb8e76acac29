// SPDX-License-Identifier: GPL-3.0-or-later
// Passage corners from a scan's differences (seed gate.c get_corners / get_center), by hand.
#include <gtest/gtest.h>

#include "modules/gate/corners.hpp"

namespace robuter::gate {
namespace {

// A scan of `near` everywhere with far sectors [first, last] (wrapping).
struct Scan {
  SectorValues f{}, d{};
  explicit Scan(std::int32_t near = 1500) { f.fill(near); }
  Scan& far(int first, int last, std::int32_t v = 2546) {
    for (int i = first;; i = ptu::wrap_sector(i + 1)) {
      f[static_cast<std::size_t>(i)] = v;
      if (i == last) break;
    }
    return *this;
  }
  Scan& set(int i, std::int32_t v) {
    f[static_cast<std::size_t>(i)] = v;
    return *this;
  }
  CornerLock lock(CornerSettings s = {}) {
    ptu::differences(f, d);
    return find_corners(d, f, s);
  }
};

// d[1] = 2546 − 1500 > 300 opens, d[4] = 1520 − 2546 < −300 closes: right 1, left 5, 3 far.
TEST(Corners, NarrowPassageLocks) {
  Scan s;
  s.far(2, 4).set(5, 1520);
  const CornerLock c = s.lock();
  ASSERT_TRUE(c.locked);
  EXPECT_EQ(c.right, 1);
  EXPECT_EQ(c.left, 5);
  EXPECT_EQ(c.gap_sectors, 3);
  EXPECT_EQ(c.right_value, 1500);
  EXPECT_EQ(c.left_value, 1520);
  EXPECT_EQ(center_sector(c.left, c.right), 3);
}

// Seven far sectors still lock (in_door 7 < 8); eight do not.
TEST(Corners, WidthLimitIsFewerThanEightSectors) {
  EXPECT_TRUE(Scan().far(10, 16).lock().locked);
  EXPECT_FALSE(Scan().far(10, 17).lock().locked);
}

// The first candidate is too wide; the walk goes on to the next positive transition.
TEST(Corners, TakesTheFirstCandidateThatLocks) {
  const CornerLock c = Scan().far(10, 18).far(30, 31).lock();
  ASSERT_TRUE(c.locked);
  EXPECT_EQ(c.right, 29);
  EXPECT_EQ(c.left, 32);
}

// Transitions of 300 mm exactly are not transitions (strict inequalities of the seed).
TEST(Corners, MarginIsStrict) {
  EXPECT_FALSE(Scan().far(10, 11, 1800).lock().locked);
  EXPECT_TRUE(Scan().far(10, 11, 1801).lock().locked);
}

// An opening that closes only far round the circle is no passage, and the walk ends there (the
// seed's walk had no bound); a flat scan has no transition at all.
TEST(Corners, WideOpeningOrFlatScanDoesNotLock) {
  EXPECT_FALSE(Scan().far(10, 71).lock().locked);
  EXPECT_FALSE(Scan().lock().locked);
}

// A passage across sector 0: the centre wraps (the seed's get_center went negative).
TEST(Corners, PassageAcrossTheWrap) {
  const CornerLock c = Scan().far(70, 0).lock();
  ASSERT_TRUE(c.locked);
  EXPECT_EQ(c.right, 69);
  EXPECT_EQ(c.left, 1);
  EXPECT_EQ(center_sector(c.left, c.right), 71);  // (1 + 72 + 69) / 2 = 71
  EXPECT_EQ(center_sector(5, 1), 3);
  EXPECT_EQ(center_sector(2, 68), 71);            // seed: (74 + 68)/2 − 72 = −1
}

}  // namespace
}  // namespace robuter::gate
