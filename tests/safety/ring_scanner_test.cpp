// The ring's firing sequence on a scripted ring: order, node delay, skipped nodes, table changes
// on the next scan, no-echo ranges, lost readings, USN/USS statistics.
#include <gtest/gtest.h>

#include "modules/us/ring_scanner.hpp"
#include "tests/safety/fakes.hpp"

namespace robuter::sonar {
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
}  // namespace robuter::sonar
