// SPDX-License-Identifier: GPL-3.0-or-later
// The demonstration course's parameters ([demo]): the table (compiled once, not in every includer of the configuration).
#include "modules/demo/demo_params.hpp"

namespace robuter {

std::span<const param::Param<DemoConfig>> demo_params() {
  using P = param::Param<DemoConfig>;
  static constexpr P kRows[] = {
      P::flag("enabled", &DemoConfig::enabled, "drive the course from start-up"),
      P::integer("distx_mm", &DemoConfig::distx_mm, "mm", 100, 10'000, "front sensor to the front box when calibrated (DISTX 12000 × 0.1 mm)"),
      P::integer("disty_mm", &DemoConfig::disty_mm, "mm", 100, 10'000, "side sensors to the calibration boxes on the lane (DISTY)"),
      P::integer("raio_mm", &DemoConfig::raio_mm, "mm", 400, 10'000, "radius of the half-circles (RAIO)"),
      P::integer("straight_mm", &DemoConfig::straight_mm, "mm", 0, 100'000, "the straight leg after the recalibration point"),
      P::integer("lane_mm", &DemoConfig::lane_mm, "mm", 0, 100'000, "the lane driven back before calibrating"),
      P::integer("speed_cm_s", &DemoConfig::speed_cm_s, "cm/s", 1, 100, "cruising wheel speed"),
      P::integer("slow_cm_s", &DemoConfig::slow_cm_s, "cm/s", 1, 100, "approach and calibration circle speed"),
      P::integer("align_cm_s", &DemoConfig::align_cm_s, "cm/s", 1, 100, "the turning wheel while aligning"),
      P::integer("sensor_a", &DemoConfig::sensor_a, "sensor", 1, robot::kRingSensors, "side sensors that must read alike (seed text: 17 and 19)"),
      P::integer("sensor_b", &DemoConfig::sensor_b, "sensor", 1, robot::kRingSensors, "the other one (seed text: 19)"),
      P::integer("front_sensor", &DemoConfig::front_sensor, "sensor", 1, robot::kRingSensors, "the sensor that measures DISTX"),
      P::integer("align_tolerance_mm", &DemoConfig::align_tolerance_mm, "mm", 1, 1000, "side readings this close count as alike"),
      P::integer("calibration_readings", &DemoConfig::calibration_readings, "readings", 1, demo::kMaxCalibrationReadings, "each calibration figure is the median of this many fresh readings (1: the seed's one)"),
      P::integer("laps", &DemoConfig::laps, "", 0, 1'000'000, "laps, then stop (the seed ended its program after n > 5: DOORS.md DM-2); 0 = for ever"),
      P::integer("calibration_timeout_ticks", &DemoConfig::calibration_timeout_ticks, "ticks", 0, 10'000'000, "align + advance longer than this: failed no-landmark, ticks (0: no limit)"),
  };
  return kRows;
}

}  // namespace robuter
