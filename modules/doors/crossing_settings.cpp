// SPDX-License-Identifier: GPL-3.0-or-later
// The door crossing's settings: [doors] with units converted, the body from the robot model, the pan-tilt's echo geometry as given.
#include "modules/doors/crossing_settings.hpp"

namespace robuter::doors {

CrossingSettings crossing_settings(const DoorsConfig& d, const robot::RobotModel& m, const ptu::EchoGeometry& echoes) {
  CrossingSettings s;
  s.body = body_geometry(m, static_cast<std::int32_t>(d.safety_mm));
  s.echoes = echoes;
  s.speeds.forward_cm_s = static_cast<std::int32_t>(d.forward_cm_s);
  s.speeds.back_cm_s = static_cast<std::int32_t>(d.back_cm_s);
  s.spread_weight = d.echo_spread_percent / 100.0;
  s.max_dist_mm = static_cast<std::int32_t>(d.max_dist_mm);
  s.time_before_move_ticks = d.time_before_move_ticks;
  s.entered_mm = static_cast<std::int32_t>(d.entered_mm);
  s.beside_mm = d.beside_mm;
  s.exit_mm = d.exit_mm;
  s.max_age_ticks = d.max_age_ticks;
  s.timeout_ticks = d.timeout_ticks;
  return s;
}

}  // namespace robuter::doors
