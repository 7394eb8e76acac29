// SPDX-License-Identifier: GPL-3.0-or-later
// The demonstration course's parameters ([demo]).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/param.hpp"
#include "robot/ring_wiring.hpp"

namespace robuter {

namespace demo {
inline constexpr int kMaxCalibrationReadings = 9;  // the most readings a calibration median takes
}  // namespace demo

// The demonstration course (seed dem.c, annex A; docs/DOORS.md).
struct DemoConfig {
  bool enabled = false;                      // drive the course from start-up
  std::uint32_t distx_mm = 1200;             // front sensor to the front box when calibrated (DISTX 12000 × 0.1 mm)
  std::uint32_t disty_mm = 1000;             // side sensors to the calibration boxes on the lane (DISTY)
  std::uint32_t raio_mm = 1000;              // radius of the half-circles (RAIO)
  std::uint32_t straight_mm = 2500;          // the straight leg after the recalibration point
  std::uint32_t lane_mm = 2100;              // the lane driven back before calibrating
  std::uint32_t speed_cm_s = 20;             // cruising wheel speed
  std::uint32_t slow_cm_s = 10;              // approach and calibration circle speed
  std::uint32_t align_cm_s = 1;              // the turning wheel while aligning
  std::uint32_t sensor_a = 17;               // side sensors that must read alike (seed text: 17 and 19)
  std::uint32_t sensor_b = 19;               // the other one (seed text: 19)
  std::uint32_t front_sensor = 1;            // the sensor that measures DISTX
  std::uint32_t align_tolerance_mm = 5;      // side readings this close count as alike
  std::uint32_t calibration_readings = 3;    // each calibration figure is the median of this many fresh readings (1: the seed's one)
  std::uint32_t laps = 6;                    // laps, then stop (the seed ended its program after n > 5: DOORS.md DM-2); 0 = for ever
  std::uint32_t calibration_timeout_ticks = 6000;  // align + advance longer than this: failed no-landmark, ticks (0: no limit)
};

// [demo]: each key, its unit, range and doc (the default is the field's initialiser).
std::span<const param::Param<DemoConfig>> demo_params();

}  // namespace robuter
