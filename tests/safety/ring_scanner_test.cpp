// SPDX-License-Identifier: GPL-3.0-or-later
// The ring's firing sequence on a scripted ring: order, node delay, skipped nodes, table changes
// on the next scan, no-echo ranges, lost readings, USN/USS statistics; the watch schedule while moving.
#include <gtest/gtest.h>

#include "modules/us/ring_scanner.hpp"
#include "tests/safety/fakes.hpp"

namespace robuter::us {
namespace {

constexpr Nanos kTick = 10 * kNanosPerMilli;

// A scanner stepped every tick (period 1) on a virtual clock.
struct ScanRig {
  ScanRig() : ring(clock) {}
  // Steps ticks [tick, tick + n) with `want`; returns how many steps changed the ranges.
  int run(int n) {
    int changed = 0;
    for (int i = 0; i < n; ++i) {
      if (scanner.step(tick, ring, want)) ++changed;
      ++tick;
      clock.advance(kTick);
    }
    return changed;
  }
  VirtualClock clock;
  test::FakeRing ring;
  RingScanner scanner;
  ScanRequest want;  // all 24, delay 3, 33 ms = 4 ticks
  std::uint64_t tick = 0;
};

TEST(RingScanner, FiresEveryActiveNodeInOrderWaitingTheDelayAfterEachRead) {
  ScanRig r;
  r.run(43);
  ASSERT_GE(r.ring.firings(), 6u);
  for (int n = 0; n < 6; ++n) {
    EXPECT_EQ(r.ring.firing(n).node, n);
    EXPECT_EQ(r.ring.firing(n).mask, 0xF);
    // Fire at 3, read at 7 (33 ms later, rounded up to the tick), next fire 3 ticks after.
    EXPECT_EQ(r.ring.firing(n).at, (3 + 7 * n) * kTick) << "node " << n;
  }
  EXPECT_EQ(r.ring.configures, 1);
  EXPECT_EQ(r.scanner.ranges().scans, 1u);
  for (int s = 1; s <= 24; ++s) {
    EXPECT_EQ(r.scanner.ranges().mm[s - 1], 3000) << s;
    EXPECT_EQ(r.scanner.ranges().read_tick[s - 1], static_cast<std::uint64_t>(7 + 7 * hal::sensor_node(s))) << s;
  }
}

TEST(RingScanner, OnlyNodesWithActiveSensorsFireAndInactiveSensorsReadZero) {
  ScanRig r;
  r.want.active = (1u << 0) | (1u << 1) | (1u << 12);  // sensors 1, 2 (node 0) and 13 (node 3)
  r.run(30);
  ASSERT_GE(r.ring.firings(), 2u);
  EXPECT_EQ(r.ring.firing(0).node, 0);
  EXPECT_EQ(r.ring.firing(0).mask, 0b0011);
  EXPECT_EQ(r.ring.firing(1).node, 3);
  EXPECT_EQ(r.ring.firing(1).mask, 0b0001);
  const auto& mm = r.scanner.ranges().mm;
  EXPECT_EQ(mm[0], 3000);
  EXPECT_EQ(mm[1], 3000);
  EXPECT_EQ(mm[12], 3000);
  for (int s : {3, 4, 5, 12, 14, 24}) EXPECT_EQ(mm[s - 1], 0) << s;
}

TEST(RingScanner, ATableChangeAppliesOnTheNextScan) {
  ScanRig r;
  r.run(10);  // inside the first scan (node 0 read at 7, node 1 fired at 10)
  r.want.active = 1u;  // sensor 1 only
  r.run(32);  // the first scan goes on with all six nodes (node 5 fired at 38)
  EXPECT_EQ(r.ring.firings(), 6u);
  EXPECT_EQ(r.scanner.ranges().mm[4], 3000) << "still the old table until the scan ends";
  r.run(1);  // tick 42: the last read ends the scan and the next one starts
  EXPECT_EQ(r.scanner.ranges().mm[4], 0) << "switched off: reads 0";
  EXPECT_EQ(r.scanner.ranges().mm[23], 0);
  EXPECT_EQ(r.scanner.ranges().mm[0], 3000);
  r.run(20);
  for (std::uint64_t i = 6; i < r.ring.firings(); ++i) {
    EXPECT_EQ(r.ring.firing(i).node, 0);
    EXPECT_EQ(r.ring.firing(i).mask, 1);
  }
}

TEST(RingScanner, NoEchoReadsAsTheTimeOutRange) {
  ScanRig r;
  r.ring.world[0] = 0;  // nothing within 5 m
  r.run(10);
  EXPECT_EQ(r.scanner.ranges().mm[0], 33u * 300u / 2u);
  EXPECT_EQ(r.scanner.ranges().no_echo, 1u);
  r.ring.world[0] = 800;
  r.run(40);
  EXPECT_EQ(r.scanner.ranges().mm[0], 800);
  EXPECT_EQ(r.scanner.ranges().no_echo, 0u);
}

TEST(RingScanner, NodeAndFullScanStatistics) {
  ScanRig r;
  r.run(43 + 42);  // two full scans
  EXPECT_EQ(r.scanner.stats().mean_node(), 7u);
  EXPECT_EQ(r.scanner.stats().mean_scan(), 42u);
  EXPECT_EQ(r.scanner.stats().scans, 2u);
}

TEST(RingScanner, FullScanTimeOnlyWhenEveryNodeHasAnActiveSensor) {
  ScanRig r;
  r.want.active = 0xFFFFFFu & ~0xFu;  // node 0 has nothing
  r.run(200);
  EXPECT_GT(r.scanner.stats().mean_node(), 0u);
  EXPECT_EQ(r.scanner.stats().mean_scan(), 0u);
  EXPECT_GE(r.scanner.ranges().scans, 4u);
}

TEST(RingScanner, NodeDelayAndTimeOutChangesApplyOnTheNextScan) {
  ScanRig r;
  r.run(42);  // up to the last node of the first scan
  r.want.node_delay_ticks = 0;
  r.want.timeout_ms = 15;
  r.want.timeout_ticks = 2;
  r.run(20);
  EXPECT_EQ(r.ring.configures, 2);
  EXPECT_EQ(r.ring.timeout_ms(), 15u);
  EXPECT_EQ(r.ring.firing(6).at, 42 * kTick) << "no delay any more: fired as the scan starts";
  EXPECT_EQ(r.ring.firing(7).at, 44 * kTick) << "read 15 ms later, next node fired at once";
}

TEST(RingScanner, LostReadingsReadZeroSoTheEmergencyHolds) {
  ScanRig r;
  r.run(43);
  EXPECT_EQ(r.scanner.ranges().mm[0], 3000);
  r.ring.never_ready = true;
  r.run(30);
  EXPECT_EQ(r.scanner.ranges().mm[0], 0);
  EXPECT_GE(r.scanner.lost_reads(), 1u);
}

TEST(RingScanner, ABusyRingIsDroppedAfterTheGrace) {
  ScanRig r;
  r.ring.refuse_fire = true;
  r.run(3 + RingScanner::kGraceTicks + 2);
  EXPECT_EQ(r.scanner.lost_reads(), 1u);
}

TEST(RingScanner, NothingActiveStaysIdle) {
  ScanRig r;
  r.want.active = 0;
  EXPECT_EQ(r.run(50), 0);
  EXPECT_EQ(r.ring.firings(), 0u);
}

// Moving straight ahead: the watch-dog set {23, 24, 1, 2, 3} on nodes 0 and 5, listening 8 ms
// (1200 mm at 300 m/s), the other firings 20 ms.
void watch_straight(ScanRig& r) {
  r.want.priority = (1u << 22) | (1u << 23) | 0b111u;
  r.want.priority_timeout_ms = 8;
  r.want.priority_timeout_ticks = 1;
  r.want.moving_timeout_ms = 20;
  r.want.moving_timeout_ticks = 2;
}

TEST(RingScanner, MovingTheWatchSetFiresEveryOtherFiringTheRotationBetween) {
  ScanRig r;
  watch_straight(r);
  r.run(200);
  // The watch firing: sensors 1, 2, 3 (node 0) and 23, 24 (node 5) at once, 8 ms; between two
  // of them, the rotation over every node, whole, 20 ms. Each logged per node.
  struct Want {
    int node;
    std::uint8_t mask;
    std::uint32_t ms;
  };
  constexpr std::uint8_t kAll = 0xF, k123 = 0b0111, k2324 = 0b1100;
  const Want seq[] = {{0, k123, 8}, {5, k2324, 8}, {0, kAll, 20}, {0, k123, 8}, {5, k2324, 8}, {1, kAll, 20},
                      {0, k123, 8}, {5, k2324, 8}, {2, kAll, 20}, {0, k123, 8}, {5, k2324, 8}, {3, kAll, 20},
                      {0, k123, 8}, {5, k2324, 8}, {4, kAll, 20}, {0, k123, 8}, {5, k2324, 8}, {5, kAll, 20},
                      {0, k123, 8}, {5, k2324, 8}, {0, kAll, 20}};
  ASSERT_GE(r.ring.firings(), std::size(seq));
  Nanos ready = 0;  // when the previous firing was read
  for (std::size_t i = 0; i < std::size(seq); ++i) {
    const auto& f = r.ring.firing(i);
    EXPECT_EQ(f.node, seq[i].node) << "firing " << i;
    EXPECT_EQ(f.mask, seq[i].mask) << "firing " << i;
    EXPECT_EQ(f.timeout_ms, seq[i].ms) << "firing " << i;
    const bool same_firing = i > 0 && seq[i].node == 5 && seq[i].mask == k2324;
    if (same_firing) {
      EXPECT_EQ(f.at, r.ring.firing(i - 1).at) << "both watch nodes fire together, firing " << i;
      continue;
    }
    // The node delay (3 ticks) after each read, the read at the first tick the node reported.
    if (i > 0) {
      EXPECT_EQ(f.at, ready + 3 * kTick) << "firing " << i;
    }
    ready = f.at + (f.timeout_ms == 8 ? 1 : 2) * kTick;
  }
  EXPECT_EQ(r.ring.configures, 1) << "the full time-out stays configured; each firing carries its own";
  EXPECT_GE(r.scanner.ranges().scans, 2u) << "a rotation over the six nodes is a scan";
}

TEST(RingScanner, MovingAShortenedFiringWithoutEchoReadsAsItsReach) {
  ScanRig r;
  watch_straight(r);
  r.ring.world[0] = 3000;  // sensor 1: beyond the 8 ms firing's 1200 mm
  r.ring.world[1] = 700;   // sensor 2: within it
  r.run(3 + 1 + 1);        // the watch firing (3) is read (4)
  EXPECT_EQ(r.scanner.ranges().mm[0], 1200);
  EXPECT_EQ(r.scanner.ranges().no_echo & 1u, 1u) << "nothing within 1200 mm";
  EXPECT_EQ(r.scanner.ranges().mm[1], 700);
  EXPECT_EQ(r.scanner.ranges().no_echo & 2u, 0u);
  EXPECT_EQ(r.scanner.ranges().mm[3], 0) << "sensor 4 is not in the watch set: not read yet";
  r.run(5);  // the rotation's 20 ms firing of node 0 (7, read at 9): 3000 mm is within its reach
  EXPECT_EQ(r.scanner.ranges().mm[0], 3000);
  EXPECT_EQ(r.scanner.ranges().no_echo & 1u, 0u);
  EXPECT_EQ(r.scanner.ranges().mm[3], 3000);
}

TEST(RingScanner, MovingAWatchSetFiresAtTheNextFiringAndStoppingRestartsTheSeedOrder) {
  ScanRig r;
  r.run(10);  // stopped: node 0 read at 7, node 1 due at 10
  watch_straight(r);
  r.run(1);  // tick 10: the robot moves, so the watch firing replaces node 1
  ASSERT_EQ(r.ring.firings(), 3u);
  EXPECT_EQ(r.ring.firing(1).node, 0);
  EXPECT_EQ(r.ring.firing(2).node, 5);
  EXPECT_EQ(r.ring.firing(2).timeout_ms, 8u);
  EXPECT_EQ(r.ring.firing(2).at, 10 * kTick);
  r.want.priority = 1u << 12 | 1u << 11 | 1u << 13;  // backwards now: sensors 12, 13, 14 (nodes 2 and 3)
  r.run(4);  // read at 11; due at 14: the new watch set fires before the rotation
  ASSERT_EQ(r.ring.firings(), 5u);
  EXPECT_EQ(r.ring.firing(3).node, 2);
  EXPECT_EQ(r.ring.firing(3).mask, 0b1000);
  EXPECT_EQ(r.ring.firing(4).node, 3);
  EXPECT_EQ(r.ring.firing(4).mask, 0b0011);
  r.want.priority = 0;  // stopped
  r.run(30);
  // Read at 15, due at 18: the seed's order starts again from node 0.
  ASSERT_GE(r.ring.firings(), 7u);
  EXPECT_EQ(r.ring.firing(5).node, 0);
  EXPECT_EQ(r.ring.firing(5).at, 18 * kTick);
  EXPECT_EQ(r.ring.firing(5).timeout_ms, 33u);
  EXPECT_EQ(r.ring.firing(6).node, 1);
  EXPECT_EQ(r.ring.firing(6).at, 25 * kTick);
}

TEST(RingScanner, TheSeedScheduleIgnoresThePriority) {
  ScanRig r;
  watch_straight(r);
  r.want.watch = false;
  r.run(43);
  ASSERT_GE(r.ring.firings(), 6u);
  for (int n = 0; n < 6; ++n) {
    EXPECT_EQ(r.ring.firing(n).node, n);
    EXPECT_EQ(r.ring.firing(n).timeout_ms, 33u);
  }
}

TEST(RingScanner, MovingWithOnlyTheWatchSetActiveTheRotationCoversIt) {
  ScanRig r;
  watch_straight(r);
  r.want.active = r.want.priority;  // auto-toggle: the watch-dog set alone
  r.run(100);
  ASSERT_GE(r.ring.firings(), 8u);
  // Watch (nodes 0 and 5), rotation node 0, watch, rotation node 5.
  const int nodes[] = {0, 5, 0, 0, 5, 5, 0, 5};
  for (std::size_t i = 0; i < std::size(nodes); ++i) EXPECT_EQ(r.ring.firing(i).node, nodes[i]) << i;
  EXPECT_EQ(r.ring.firing(2).mask, 0b0111) << "the rotation fires the node's active sensors: 1, 2, 3";
  EXPECT_EQ(r.ring.firing(2).timeout_ms, 20u);
  EXPECT_GE(r.scanner.ranges().scans, 2u) << "a rotation over nodes 0 and 5 is a scan";
}

TEST(RingScanner, MovingAWatchNodeThatNeverReportsIsDroppedAlone) {
  ScanRig r;
  watch_straight(r);
  r.run(5);
  EXPECT_EQ(r.scanner.ranges().mm[0], 1200);
  r.ring.never_ready = true;
  r.run(40);
  EXPECT_EQ(r.scanner.ranges().mm[0], 0) << "lost: no data, so the gate holds";
  EXPECT_EQ(r.scanner.ranges().mm[23], 0);
  EXPECT_GE(r.scanner.lost_reads(), 2u);
}

TEST(NodeMasks, SplitsTheTableByNode) {
  const NodeMasks m = node_masks((1u << 0) | (1u << 5) | (1u << 23));
  EXPECT_EQ(m[0], 0b0001);
  EXPECT_EQ(m[1], 0b0010);
  EXPECT_EQ(m[5], 0b1000);
  EXPECT_EQ(next_node(m, -1), 0);
  EXPECT_EQ(next_node(m, 0), 1);
  EXPECT_EQ(next_node(m, 1), 5);
  EXPECT_EQ(next_node(m, 5), -1);
}

}  // namespace
}  // namespace robuter::us
