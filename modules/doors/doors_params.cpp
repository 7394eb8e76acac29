// SPDX-License-Identifier: GPL-3.0-or-later
// The door crossing's parameters ([doors]): the table (compiled once, not in every includer of the configuration).
#include "modules/doors/doors_params.hpp"

namespace robuter {

std::span<const param::Param<DoorsConfig>> doors_params() {
  using P = param::Param<DoorsConfig>;
  static constexpr P kRows[] = {
      P::integer("safety_mm", &DoorsConfig::safety_mm, "mm", 0, 1000, "clearance kept from obstacles (SAFETY_DIST), mm"),
      P::integer("max_dist_mm", &DoorsConfig::max_dist_mm, "mm", 100, 20'000, "a side all beyond this: through the door (MAX_DIST), mm"),
      P::integer("time_before_move_ticks", &DoorsConfig::time_before_move_ticks, "ticks", 1, 1'000'000, "blocked on both sides this long: can't cross (TIME_BEFORE_MOVE)"),
      P::integer("forward_cm_s", &DoorsConfig::forward_cm_s, "cm/s", 1, 100, "speed going straight, cm/s"),
      P::integer("back_cm_s", &DoorsConfig::back_cm_s, "cm/s", 1, 100, "speed of the wheel that backs off in a turn, cm/s"),
      P::integer("entered_mm", &DoorsConfig::entered_mm, "mm", 100, 20'000, "both sides seen closer than this: inside the door, mm"),
      P::integer("beside_mm", &DoorsConfig::beside_mm, "mm", 10, 20'000, "and those echoes this close to abreast of the pan axis, mm"),
      P::integer("exit_mm", &DoorsConfig::exit_mm, "mm", 0, 10'000, "driven on after \"through\" so the rear clears the door, mm"),
      P::integer("max_age_ticks", &DoorsConfig::max_age_ticks, "ticks", 10, 1'000'000, "pan-tilt readings older than this are ignored, ticks"),
      P::integer("same_echo_mm", &DoorsConfig::same_echo_mm, "mm", 0, 1000, "neighbouring sectors this close in range see the same echo, mm"),
      P::integer("echo_spread_percent", &DoorsConfig::echo_spread_percent, "%", 0, 100, "an echo is judged over this share of its bearing uncertainty, %"),
      P::integer("timeout_ticks", &DoorsConfig::timeout_ticks, "ticks", 0, 100'000'000, "a crossing longer than this fails, ticks (0: no limit)"),
      P::integer("emergency_mask", &DoorsConfig::emergency_mask, "bits", 0, 7, "detections kept on while crossing (bumper 1)"),
  };
  return kRows;
}

}  // namespace robuter
