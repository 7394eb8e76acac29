// SPDX-License-Identifier: GPL-3.0-or-later
// The ultrasonic ring module's parameters ([sonar]).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "kernel/param.hpp"

namespace robuter {

// Ultrasonic ring timing (us.c).
struct SonarConfig {
  std::uint32_t node_delay_ticks = 3;    // delay between firing two nodes, ticks
  std::uint32_t timeout_ms = 33;         // echo time-out, ms (≈ 5 m at 300 m/s)
  std::uint32_t sound_speed_m_s = 300;   // calibrated speed of sound, m/s
  std::string schedule = "watch";        // firing order while moving: "watch" (where the robot goes
                                         // first and most often) or "seed" (node order, as stopped)
  std::uint32_t moving_timeout_ms = 20;  // echo time-out of the rotation's firings between two watch
                                         // firings while moving, ms (≈ 3 m; 0 = timeout_ms)
};

// [sonar]: each key, its unit, range and doc (the default is the field's initialiser).
inline constexpr param::Param<SonarConfig> kSonarParams[] = {
    {"node_delay_ticks", &SonarConfig::node_delay_ticks, "ticks", 0, 1000, "",
     "delay between firing two nodes, ticks"},
    {"timeout_ms", &SonarConfig::timeout_ms, "ms", 1, 1000, "",
     "echo time-out, ms (≈ 5 m at 300 m/s)"},
    {"sound_speed_m_s", &SonarConfig::sound_speed_m_s, "m/s", 200, 400, "",
     "calibrated speed of sound, m/s"},
    {"schedule", &SonarConfig::schedule, "", 0, 0, "watch|seed",
     "firing order while moving: \"watch\" (where the robot goes"},
    {"moving_timeout_ms", &SonarConfig::moving_timeout_ms, "ms", 0, 1000, "",
     "echo time-out of the rotation's firings between two watch"},
};

}  // namespace robuter
