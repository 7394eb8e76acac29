// SPDX-License-Identifier: GPL-3.0-or-later
// The gate's settings: [gate] with units converted (0.01° to degrees), the pan-tilt's echo geometry as given, the front face and wheel base from the robot model.
#include "modules/gate/gate_settings.hpp"

namespace robuter::gate {

GateSettings gate_settings(const GateConfig& g, const robot::RobotModel& m, const ptu::EchoGeometry& echoes) {
  GateSettings s;
  s.door.geometry = echoes;
  s.door.corners.margin_mm = static_cast<std::int32_t>(g.margin_mm);
  s.door.corners.max_gap_sectors = static_cast<int>(g.max_gap_sectors);
  s.door.max_mm = static_cast<std::int32_t>(g.max_mm);
  s.min_mm = static_cast<std::int32_t>(g.min_mm);
  s.speed_cm_s = static_cast<std::int32_t>(g.speed_cm_s);
  s.turn_cm_s = static_cast<std::int32_t>(g.turn_cm_s);
  s.timeout_ticks = g.timeout_ticks;
  s.stage_mm = g.stage_mm;
  s.lateral_tolerance_mm = g.lateral_tolerance_mm;
  s.heading_tolerance_deg = g.heading_tolerance_centideg / 100.0;
  s.max_manoeuvres = g.max_manoeuvres;
  s.stall_ticks = g.stall_ticks;
  s.back_off_mm = g.back_off_mm;
  s.axle_to_front_mm = m.body.axle_to_front * 1000.0;
  s.wheel_base_mm = robot::mm_u(m.wheels.base);
  return s;
}

}  // namespace robuter::gate
