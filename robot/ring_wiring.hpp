// SPDX-License-Identifier: GPL-3.0-or-later
// The ultrasonic ring's counts and node wiring: 24 sensors on 6 nodes of 4 (seed 002, us.c).
// Array sizes and wire formats depend on these, so they are compile-time and Eigen-free.
#pragma once

namespace robuter::robot {

inline constexpr int kRingSensors = 24;    // ultrasonic ring sensors, numbered 1..24
inline constexpr int kRingNodes = 6;       // nodes that fire them, numbered 0..5 here (seed: 1..6)
inline constexpr int kSensorsPerNode = 4;  // sensors on one node, slots 0..3 here (seed: 1..4)
static_assert(kRingNodes * kSensorsPerNode == kRingSensors);

// Node wiring: four consecutive sensors per node (node n fires sensors 4n+1 … 4n+4), the order
// the seed's cross-talk remark implies (docs/ROBOT.md, "Node wiring").
constexpr int wired_node(int sensor) { return (sensor - 1) / kSensorsPerNode; }
constexpr int wired_slot(int sensor) { return (sensor - 1) % kSensorsPerNode; }
constexpr int wired_sensor(int node, int slot) { return node * kSensorsPerNode + slot + 1; }
static_assert(wired_sensor(wired_node(17), wired_slot(17)) == 17);

}  // namespace robuter::robot
