// SPDX-License-Identifier: GPL-3.0-or-later
// The default ring table (numbering, the seed's emergency thresholds, symmetry, nodes) and the
// node firing schedule.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "hal/sim/footprint.hpp"
#include "hal/sim/sonar_timing.hpp"

namespace robuter::sim {
namespace {

// r = (a² + b²) / 2a of sensors 2..6 reproduces LIMIT12..LIMIT56 (mm), to the millimetre; the
// corner sensor 5 is within 1.5 mm of LIMIT45.
TEST(RingLayout, FrontSensorsMatchTheEmergencyThresholds) {
  const RingLayout ring = default_ring_layout();
  EXPECT_TRUE(std::isinf(trajectory_radius(ring[0])));
  EXPECT_NEAR(trajectory_radius(ring[1]), 2.476, 0.001);
  EXPECT_NEAR(trajectory_radius(ring[2]), 1.200, 0.001);
  EXPECT_NEAR(trajectory_radius(ring[3]), 1.011, 0.001);
  EXPECT_NEAR(trajectory_radius(ring[4]), 0.864, 0.0015);
  EXPECT_NEAR(trajectory_radius(ring[5]), 0.710, 0.001);
  // Mirror images on the left, with negative radii.
  EXPECT_NEAR(trajectory_radius(ring[23]), -2.476, 0.001);
  EXPECT_NEAR(trajectory_radius(ring[19]), -0.710, 0.001);
}

// 1 forward, clockwise seen from above: 7 right, 13 rear, 19 left; every sensor on the body
// outline; left half mirrors the right.
TEST(RingLayout, NumberingAndPlacement) {
  const RingLayout ring = default_ring_layout();
  const RobotGeometry g;
  const Box body = g.body();
  for (int i = 0; i < kRingSensors; ++i) {
    SCOPED_TRACE(i + 1);
    const SonarMount& m = ring[i];
    EXPECT_EQ(m.number, i + 1);
    const bool on_x_face = std::abs(m.position.x() - body.hi.x()) < 1e-9 ||
                           std::abs(m.position.x() - body.lo.x()) < 1e-9;
    const bool on_y_face = std::abs(std::abs(m.position.y()) - body.hi.y()) < 1e-9;
    EXPECT_TRUE(on_x_face || on_y_face);
    EXPECT_GE(m.position.x(), body.lo.x() - 1e-9);
    EXPECT_LE(m.position.x(), body.hi.x() + 1e-9);
    if (i >= 1 && i <= 11) {
      const SonarMount& mirror = ring[24 - i];  // sensor 26 - (i + 1)
      EXPECT_DOUBLE_EQ(mirror.position.x(), m.position.x());
      EXPECT_DOUBLE_EQ(mirror.position.y(), -m.position.y());
      EXPECT_NEAR(mirror.direction, -m.direction, 1e-12);
    }
  }
  EXPECT_NEAR(ring[0].direction, 0.0, 1e-12);
  EXPECT_NEAR(ring[6].direction, -kPi / 2, 1e-12);
  EXPECT_NEAR(std::abs(ring[12].direction), kPi, 1e-12);
  EXPECT_NEAR(ring[18].direction, kPi / 2, 1e-12);
  // Clockwise: directions decrease from sensor 1 to 13 on the right half.
  for (int i = 1; i <= 11; ++i) EXPECT_LE(ring[i].direction, ring[i - 1].direction + 1e-12);
  // The seed's calibration sensors 17 and 19 both look straight left.
  EXPECT_NEAR(ring[16].direction, kPi / 2, 1e-12);
}

// Every node fires four sensors, one per slot (the robot model's wiring).
TEST(RingLayout, NodesHoldFourSensorsEach) {
  std::array<std::array<int, 4>, kRingNodes> seen{};
  for (const auto& m : robot::kRobuter.ring.sensors) {
    ASSERT_GE(m.node, 0);
    ASSERT_LT(m.node, kRingNodes);
    ASSERT_GE(m.slot, 0);
    ASSERT_LT(m.slot, 4);
    ++seen[m.node][m.slot];
  }
  for (int n = 0; n < kRingNodes; ++n)
    for (int s = 0; s < 4; ++s) EXPECT_EQ(seen[n][s], 1) << "node " << n << " slot " << s;
}

// All nodes: delay, fire, wait the time-out, delay, fire... 6 × 63 ms.
TEST(RingTiming, FullScanSchedule) {
  std::array<bool, kRingSensors> active{};
  active.fill(true);
  std::array<NodeFiring, kRingNodes> out{};
  const RingTiming t;
  const int n = plan_scan(active, t, 10.0, out);
  ASSERT_EQ(n, 6);
  for (int i = 0; i < n; ++i) {
    EXPECT_EQ(out[i].node, i + 1);
    EXPECT_NEAR(out[i].fire, 10.0 + 0.030 * (i + 1) + 0.033 * i, 1e-12);
    EXPECT_NEAR(out[i].ready, out[i].fire + 0.033, 1e-12);
  }
  EXPECT_NEAR(out[5].ready - 10.0, scan_duration(6, t), 1e-12);
}

TEST(RingTiming, OnlyNodesWithActiveSensorsFire) {
  std::array<bool, kRingSensors> active{};
  active[8] = true;   // sensor 9: node 3 (sensors 9-12)
  active[19] = true;  // sensor 20: node 5 (sensors 17-20)
  std::array<NodeFiring, kRingNodes> out{};
  const int n = plan_scan(active, RingTiming{}, 0.0, out);
  ASSERT_EQ(n, 2);
  EXPECT_EQ(out[0].node, 3);
  EXPECT_EQ(out[1].node, 5);
  EXPECT_NEAR(out[1].fire, out[0].ready + 0.030, 1e-12);
  EXPECT_DOUBLE_EQ(node_ready_time(1.0, 0.033), 1.033);
  EXPECT_DOUBLE_EQ(echo_time(1.5, 300.0), 0.01);
}

}  // namespace
}  // namespace robuter::sim
