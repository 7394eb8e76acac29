// SPDX-License-Identifier: GPL-3.0-or-later
// The ultrasonic ring module's parameters ([sonar]): the table (compiled once, not in every includer of the configuration).
#include "modules/us/sonar_params.hpp"

namespace robuter {

std::span<const param::Param<SonarConfig>> sonar_params() {
  using P = param::Param<SonarConfig>;
  static constexpr P kRows[] = {
      P::integer("node_delay_ticks", &SonarConfig::node_delay_ticks, "ticks", 0, 1000, "delay between firing two nodes, ticks"),
      P::integer("timeout_ms", &SonarConfig::timeout_ms, "ms", 1, 1000, "echo time-out, ms (≈ 5 m at 300 m/s)"),
      P::integer("sound_speed_m_s", &SonarConfig::sound_speed_m_s, "m/s", 200, 400, "calibrated speed of sound, m/s"),
      P::word("schedule", &SonarConfig::schedule, "watch|seed", "firing order while moving: \"watch\" (where the robot goes"),
      P::integer("moving_timeout_ms", &SonarConfig::moving_timeout_ms, "ms", 0, 1000, "echo time-out of the rotation's firings between two watch"),
  };
  return kRows;
}

}  // namespace robuter
