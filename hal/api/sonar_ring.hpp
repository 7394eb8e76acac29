// SPDX-License-Identifier: GPL-3.0-or-later
// HAL: the ultrasonic ring — nodes of four sensors fired single-shot, ranges read back.
#pragma once

#include <array>
#include <cstdint>

#include "robot/ring_wiring.hpp"

namespace robuter::hal {

inline constexpr int kSonarNodes = robot::kRingNodes;            // nodes on the ring
inline constexpr int kSensorsPerNode = robot::kSensorsPerNode;   // sensors per node
inline constexpr int kRingSensors = robot::kRingSensors;         // sensors on the ring
inline constexpr int kPanTiltChannel = 7;      // channel of the pan-tilt's two sonars (seed)

// Ranges of one node's four sensors, mm; 0 = inactive or no echo within the time-out.
using NodeRanges = std::array<std::uint16_t, kSensorsPerNode>;

// Sensor number 1..24 ↔ (node 0..5, index 0..3), as the robot model wires them (four
// consecutive sensors per node). Sensor 1 looks forward; numbers run clockwise.
constexpr int sensor_node(int sensor) { return robot::wired_node(sensor); }
constexpr int sensor_index(int sensor) { return robot::wired_slot(sensor); }
constexpr int sensor_number(int node, int index) { return robot::wired_sensor(node, index); }

class SonarRing {
 public:
  virtual ~SonarRing() = default;
  // Echo time-out (ms) and speed of sound (m/s) used to turn echo times into ranges.
  virtual void configure(std::uint32_t timeout_ms, std::uint32_t sound_speed_m_s) = 0;
  // Fires the sensors of `mask` (bit i = index i) on `node` (0..5, or kPanTiltChannel with
  // mask bits 0 and 1 for the pan-tilt's two sonars). `timeout_ms` is this firing's listening
  // time-out, ms: 0 = the configured one; a shorter one makes the node report sooner and only
  // echoes within timeout_ms · c / 2 (ignored on the pan-tilt channel, which has its own).
  // False if the node is busy or absent. Every override declares the same default.
  virtual bool fire(int node, std::uint8_t mask, std::uint32_t timeout_ms = 0) = 0;
  // The ranges of the last firing of `node` once the node reported them: when every fired
  // sensor has heard its echo, or at the firing's time-out when one has not (0 for it); false
  // until then. A node never reports later than its time-out (plus bus delays).
  virtual bool read(int node, NodeRanges& out) = 0;
};

}  // namespace robuter::hal
