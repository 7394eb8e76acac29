// SPDX-License-Identifier: GPL-3.0-or-later
// [ptu] → PtuSettings: units converted (0.01° to degrees), the rest copied.
#include "modules/ptu/ptu_settings.hpp"

namespace robuter::ptu {

PtuSettings ptu_settings(const PanTiltConfig& c) {
  PtuSettings s;
  s.min_position = c.min_position;
  s.max_position = c.max_position;
  s.speed = static_cast<std::int32_t>(c.speed);
  s.acceleration = static_cast<std::int32_t>(c.acceleration);
  s.fire_tolerance_deg = c.fire_tolerance_centideg / 100.0;
  s.reply_timeout_ticks = c.reply_timeout_ticks;
  s.poll_period_ticks = c.poll_period_ticks;
  s.max_failures = c.max_failures;
  s.calibration.cap_mm = static_cast<std::int32_t>(c.cap_mm);
  s.calibration.offset_mm = static_cast<std::int32_t>(c.offset_mm);
  s.calibration.scale_permille = static_cast<std::int32_t>(c.scale_permille);
  s.filter.high_mm = static_cast<std::int32_t>(c.filter_high_mm);
  s.filter.drop_mm = static_cast<std::int32_t>(c.filter_drop_mm);
  return s;
}

}  // namespace robuter::ptu
