// SPDX-License-Identifier: GPL-3.0-or-later
// The pan-tilt module's parameters ([ptu]).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "hal/api/serial_port_params.hpp"
#include "kernel/param.hpp"
#include "robot/robot_model.hpp"

namespace robuter {

// The pan-tilt unit and its two sonars (seed ptu.c, ptu.h; docs/DOORS.md).
// Its serial port (the base: key `port` for the device, empty = no unit) comes first.
struct PanTiltConfig : hal::SerialPortConfig {
  std::int32_t min_position = -1755;         // one end of the sweep, positions (−90.2°)
  std::int32_t max_position = 1655;          // the other end, positions (85.0°)
  std::uint32_t speed = 1500;                // pan speed, positions/s (SPEED)
  std::uint32_t acceleration = 6000;         // pan acceleration, positions/s² (PA6000)
  std::uint32_t fire_tolerance_centideg = 100;  // fire within this of a multiple of 5°, 0.01° (seed ±1°)
  std::uint32_t poll_period_ticks = 3;       // the unit's position is asked this often, ticks (seed 30 ms)
  std::uint32_t reply_timeout_ticks = 20;    // an unanswered command times out after this, ticks
  std::uint32_t max_failures = 3;            // consecutive time-outs or bad replies that fail the unit
  std::uint32_t cap_mm = 2491;               // readings above this (and no echo) count as this, mm (PAN_TIME_OUT_DIST)
  std::uint32_t offset_mm = 46;              // calibration: measured = scale · real + offset, mm
  std::uint32_t scale_permille = 960;        // calibration scale, ‰ (0.96)
  std::uint32_t filter_high_mm = 2300;       // spike filter: neighbours above this are high, mm (MAX)
  std::uint32_t filter_drop_mm = 1000;       // spike filter: a spike is below high − this, mm
  std::int32_t pivot_x_mm = robot::mm(robot::kRobuter.pan_tilt.pivot_x);  // pan axis ahead of the wheel axle (negative: behind), mm
  std::uint32_t box_width_mm = robot::mm_u(2.0 * robot::kRobuter.pan_tilt.face_offset);  // between the two transducer faces (BOX_WIDTH), mm
  std::uint32_t beam_half_angle_centideg = static_cast<std::uint32_t>(robot::centideg(robot::kRobuter.pan_tilt.half_angle));  // half-angle of a pan-tilt sonar's beam, 0.01°
};

// [ptu]: each key, its unit, range and doc (the default is the field's initialiser).
std::span<const param::Param<PanTiltConfig>> pan_tilt_params();

}  // namespace robuter
