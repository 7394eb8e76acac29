// SPDX-License-Identifier: GPL-3.0-or-later
// The ultrasonic ring module's parameters ([sonar]).
#pragma once

#include <cstdint>
#include <span>
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
std::span<const param::Param<SonarConfig>> sonar_params();

}  // namespace robuter
