// SPDX-License-Identifier: GPL-3.0-or-later
// Angles: the one fold of a heading into (−π, π] that the firmware's modules and the simulator use.
#pragma once

#include <cmath>
#include <numbers>

namespace robuter::robot {

// An angle in radians folded into (−π, π]: exact (std::remainder) and bounded work for any input
// (a loop that subtracts 2π runs for ever on a huge value).
inline double wrap_angle(double a) {
  a = std::remainder(a, 2.0 * std::numbers::pi);
  return a <= -std::numbers::pi ? a + 2.0 * std::numbers::pi : a;
}

}  // namespace robuter::robot
