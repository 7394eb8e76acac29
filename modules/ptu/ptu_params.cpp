// SPDX-License-Identifier: GPL-3.0-or-later
// The pan-tilt module's parameters ([ptu]): the table (compiled once, not in every includer of the configuration).
#include "modules/ptu/ptu_params.hpp"

#include <array>

namespace robuter {

std::span<const param::Param<PanTiltConfig>> pan_tilt_params() {
  using P = param::Param<PanTiltConfig>;
  static constexpr auto kRows = param::join(
      hal::serial_port_rows<PanTiltConfig>("port", "the unit's serial device, empty = no unit (robuterd --ptu-port)", "its rate, bit/s"),
      std::array{
        P::integer("min_position", &PanTiltConfig::min_position, "positions", -100'000, 100'000, "one end of the sweep, positions (−90.2°)"),
        P::integer("max_position", &PanTiltConfig::max_position, "positions", -100'000, 100'000, "the other end, positions (85.0°)"),
        P::integer("speed", &PanTiltConfig::speed, "positions/s", 1, 100'000, "pan speed, positions/s (SPEED)"),
        P::integer("acceleration", &PanTiltConfig::acceleration, "positions/s²", 1, 1'000'000, "pan acceleration, positions/s² (PA6000)"),
        P::integer("fire_tolerance_centideg", &PanTiltConfig::fire_tolerance_centideg, "0.01°", 1, 250, "fire within this of a multiple of 5°, 0.01° (seed ±1°)"),
        P::integer("poll_period_ticks", &PanTiltConfig::poll_period_ticks, "ticks", 1, 1000, "the unit's position is asked this often, ticks (seed 30 ms)"),
        P::integer("reply_timeout_ticks", &PanTiltConfig::reply_timeout_ticks, "ticks", 1, 10'000, "an unanswered command times out after this, ticks"),
        P::integer("max_failures", &PanTiltConfig::max_failures, "", 1, 100, "consecutive time-outs or bad replies that fail the unit"),
        P::integer("cap_mm", &PanTiltConfig::cap_mm, "mm", 100, 20'000, "readings above this (and no echo) count as this, mm (PAN_TIME_OUT_DIST)"),
        P::integer("offset_mm", &PanTiltConfig::offset_mm, "mm", 0, 1000, "calibration: measured = scale · real + offset, mm"),
        P::integer("scale_permille", &PanTiltConfig::scale_permille, "‰", 500, 1500, "calibration scale, ‰ (0.96)"),
        P::integer("filter_high_mm", &PanTiltConfig::filter_high_mm, "mm", 0, 20'000, "spike filter: neighbours above this are high, mm (MAX)"),
        P::integer("filter_drop_mm", &PanTiltConfig::filter_drop_mm, "mm", 0, 20'000, "spike filter: a spike is below high − this, mm"),
        P::integer("pivot_x_mm", &PanTiltConfig::pivot_x_mm, "mm", -5000, 5000, "pan axis ahead of the wheel axle (negative: behind), mm"),
        P::integer("box_width_mm", &PanTiltConfig::box_width_mm, "mm", 0, 1000, "between the two transducer faces (BOX_WIDTH), mm"),
        P::integer("beam_half_angle_centideg", &PanTiltConfig::beam_half_angle_centideg, "0.01°", 0, 4500, "half-angle of a pan-tilt sonar's beam, 0.01°"),
      });
  return kRows;
}

}  // namespace robuter
