// SPDX-License-Identifier: GPL-3.0-or-later
// Wheel speed commands: the one rounding of a controller's speed into the drive's whole cm/s.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace robuter::robot {

// A controller's wheel speed `v` (cm/s) as a drive command: rounded to whole cm/s, its magnitude
// clamped to lo..hi (so the wheel still moves when a controller asks for very little; 0 gives
// +lo), its sign kept. Used by the executor's go-to and the planner's path follower.
inline std::int32_t wheel_command(double v, std::int32_t lo, std::int32_t hi) {
  const double m = std::clamp(std::abs(v), static_cast<double>(lo), static_cast<double>(hi));
  const auto r = static_cast<std::int32_t>(std::lround(m));
  return v < 0 ? -r : r;
}

}  // namespace robuter::robot
