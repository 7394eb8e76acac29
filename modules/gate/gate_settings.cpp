// SPDX-License-Identifier: GPL-3.0-or-later
// Units converted: 0.01° to degrees; the pan axis and the front face from the robot model.
#include "modules/gate/gate_settings.hpp"

namespace robuter::gate {

GateSettings gate_settings(const Config& c) {
  GateSettings s;
  const robot::RobotModel m = robot_model(c);
  s.door.geometry.pivot_x_mm = m.pan_tilt.pivot_x * 1000.0;
  s.door.geometry.face_mm = m.pan_tilt.face_offset * 1000.0;
  s.door.geometry.beam_half_deg = m.pan_tilt.half_angle / robot::kDeg;
  s.door.geometry.same_echo_mm = static_cast<std::int32_t>(c.doors.same_echo_mm);
  s.door.geometry.far_mm = static_cast<std::int32_t>(c.gate.max_mm);
  s.door.corners.margin_mm = static_cast<std::int32_t>(c.gate.margin_mm);
  s.door.corners.max_gap_sectors = static_cast<int>(c.gate.max_gap_sectors);
  s.door.max_mm = static_cast<std::int32_t>(c.gate.max_mm);
  s.min_mm = static_cast<std::int32_t>(c.gate.min_mm);
  s.speed_cm_s = static_cast<std::int32_t>(c.gate.speed_cm_s);
  s.turn_cm_s = static_cast<std::int32_t>(c.gate.turn_cm_s);
  s.timeout_ticks = c.gate.timeout_ticks;
  s.stage_mm = c.gate.stage_mm;
  s.lateral_tolerance_mm = c.gate.lateral_tolerance_mm;
  s.heading_tolerance_deg = c.gate.heading_tolerance_centideg / 100.0;
  s.max_manoeuvres = c.gate.max_manoeuvres;
  s.stall_ticks = c.gate.stall_ticks;
  s.back_off_mm = c.gate.back_off_mm;
  s.axle_to_front_mm = m.body.axle_to_front * 1000.0;
  s.wheel_base_mm = c.robot.wheel_base_mm;
  return s;
}

}  // namespace robuter::gate
