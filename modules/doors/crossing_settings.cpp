// SPDX-License-Identifier: GPL-3.0-or-later
// Units converted and the seed's geometry gathered from the robot model ([robot], [ptu] mount).
#include "modules/doors/crossing_settings.hpp"

namespace robuter::doors {

CrossingSettings crossing_settings(const Config& c) {
  CrossingSettings s;
  const robot::RobotModel m = robot_model(c);
  s.body = body_geometry(m, static_cast<std::int32_t>(c.doors.safety_mm));
  s.echoes.pivot_x_mm = m.pan_tilt.pivot_x * 1000.0;
  s.echoes.face_mm = m.pan_tilt.face_offset * 1000.0;
  s.echoes.beam_half_deg = m.pan_tilt.half_angle / robot::kDeg;
  s.echoes.same_echo_mm = static_cast<std::int32_t>(c.doors.same_echo_mm);
  s.echoes.far_mm = static_cast<std::int32_t>(c.gate.max_mm);
  s.speeds.forward_cm_s = static_cast<std::int32_t>(c.doors.forward_cm_s);
  s.speeds.back_cm_s = static_cast<std::int32_t>(c.doors.back_cm_s);
  s.spread_weight = c.doors.echo_spread_percent / 100.0;
  s.max_dist_mm = static_cast<std::int32_t>(c.doors.max_dist_mm);
  s.time_before_move_ticks = c.doors.time_before_move_ticks;
  s.entered_mm = static_cast<std::int32_t>(c.doors.entered_mm);
  s.beside_mm = c.doors.beside_mm;
  s.exit_mm = c.doors.exit_mm;
  s.max_age_ticks = c.doors.max_age_ticks;
  s.timeout_ticks = c.doors.timeout_ticks;
  return s;
}

}  // namespace robuter::doors
