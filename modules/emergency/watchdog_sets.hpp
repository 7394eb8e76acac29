// SPDX-License-Identifier: GPL-3.0-or-later
// Main sensor from the wheel speeds, watch-dog sets and the auto-toggle table (seed emerg.c).
#pragma once

#include <array>
#include <cstdint>

#include "robot/ring_wiring.hpp"

namespace robuter::emergency {

inline constexpr int kRingSize = robot::kRingSensors;  // sensors on the ring, numbered 1..24
inline constexpr int kWatchSize = 5;   // watch-dog sensors per direction of motion

// Thresholds on |r|, the radius of curvature, between adjacent main sensors, mm. Each is
// r = (a²+b²)/(2a) for a sensor at (a, b) on the Robuter's body (seed: LIMIT12 … LIMIT56).
inline constexpr double kLimit12 = 2476.0;
inline constexpr double kLimit23 = 1200.0;
inline constexpr double kLimit34 = 1011.0;
inline constexpr double kLimit45 = 864.0;
inline constexpr double kLimit56 = 710.0;

// The five watch-dog sensors in the seed's order (main, −1, +1, −2, +2); all 0 when stopped.
using WatchSensors = std::array<int, kWatchSize>;

// Bit of sensor s (1..24) in a 24-bit table.
constexpr std::uint32_t sensor_bit(int s) { return 1u << static_cast<unsigned>(s - 1); }
inline constexpr std::uint32_t kAllSensors = 0xFFFFFF;  // every sensor of the ring

// Sensor numbers around the ring: a − b and a + b, wrapping within 1..24 (seed sub24/add24).
int sub24(int a, int b);
int add24(int a, int b);

// The sensor that looks along the path of wheel speeds (left, right) in cm/s: 0 stopped,
// 1 straight forward, 13 straight backward, 7 / 19 rotating right / left, 2…6 and 24…20 for
// forward curves right / left, 12…8 and 14…18 backward. `wheel_base_mm` is DBW (600).
int main_sensor(std::int32_t left, std::int32_t right, std::uint32_t wheel_base_mm);

// The watch-dog sensors of a main sensor: the main one and two neighbours each side, except
// the special sets for tight curves and rotations (6, 7, 8, 18, 19, 20).
WatchSensors watch_sensors(int main);
// The same as a table, bit s-1 = sensor s.
std::uint32_t watch_mask(int main);

// The table the ring fires: with auto-toggle only the watch-dog set (none when stopped) and the
// user table ignored; without, the user table OR the watch-dog set. When the ultrasonic
// detection is off the ring simply serves the user table.
std::uint32_t select_sensors(std::uint32_t user_table, bool auto_toggle, std::uint32_t watch, bool us_enabled);

}  // namespace robuter::emergency
