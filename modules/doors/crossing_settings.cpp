// Units converted and the seed's geometry gathered: body from [robot], pan-tilt from [doors]/[ptu].
#include "modules/doors/crossing_settings.hpp"

namespace robuter::doors {

CrossingSettings crossing_settings(const Config& c) {
  CrossingSettings s;
  s.body.length_mm = static_cast<std::int32_t>(c.robot.length_mm);
  s.body.width_mm = static_cast<std::int32_t>(c.robot.width_mm);
  s.body.pan_x_mm = static_cast<std::int32_t>(c.doors.pan_x_mm);
  s.body.pan_y_mm = static_cast<std::int32_t>(c.doors.pan_y_mm);
  s.body.box_width_mm = static_cast<std::int32_t>(c.doors.box_width_mm);
  s.body.safety_mm = static_cast<std::int32_t>(c.doors.safety_mm);
  s.echoes.pivot_x_mm = c.ptu.pivot_x_mm;
  s.echoes.face_mm = c.doors.box_width_mm / 2.0;
  s.echoes.beam_half_deg = c.ptu.beam_half_angle_centideg / 100.0;
  s.echoes.same_echo_mm = static_cast<std::int32_t>(c.doors.same_echo_mm);
  s.echoes.far_mm = static_cast<std::int32_t>(c.gate.max_mm);
  s.speeds.forward_cm_s = static_cast<std::int32_t>(c.doors.forward_cm_s);
  s.speeds.back_cm_s = static_cast<std::int32_t>(c.doors.back_cm_s);
  s.spread_weight = c.doors.echo_spread_percent / 100.0;
  s.max_dist_mm = static_cast<std::int32_t>(c.doors.max_dist_mm);
  s.time_before_move_ticks = c.doors.time_before_move_ticks;
  s.entered_mm = static_cast<std::int32_t>(c.doors.entered_mm);
  s.exit_mm = c.doors.exit_mm;
  s.max_age_ticks = c.doors.max_age_ticks;
  s.timeout_ticks = c.doors.timeout_ticks;
  return s;
}

}  // namespace robuter::doors
