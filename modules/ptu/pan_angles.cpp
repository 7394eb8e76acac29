// SPDX-License-Identifier: GPL-3.0-or-later
// The seed's angle arithmetic, reproduced digit for digit (read_pt's last-digit rounding).
#include "modules/ptu/pan_angles.hpp"

#include <cmath>

namespace robuter::ptu {

int position_to_degrees(std::int32_t position) { return static_cast<int>(position * 185 / 3600); }

// Why the last digit: the seed printed the angle and looked at its last character; 4 and 9 move
// one degree away from zero, 1 and 6 one degree towards it — in both cases onto a multiple of 5.
int sector_of_degrees(int degrees) {
  int a = degrees;
  const int last = (a < 0 ? -a : a) % 10;
  if (last == 4 || last == 9) a += a > 0 ? 1 : -1;
  else if (last == 1 || last == 6) a += a > 0 ? -1 : 1;
  if (a % kSectorDegrees != 0 || a < -90 || a > 85) return -1;
  return (a + 90) / kSectorDegrees;
}

double position_to_angle(double position) { return position * 185.0 / 3600.0; }

int sector_near(double degrees, double tolerance_deg) {
  const double k = std::round(degrees / kSectorDegrees);
  if (std::abs(degrees - k * kSectorDegrees) > tolerance_deg) return -1;
  const int a = static_cast<int>(k) * kSectorDegrees;
  if (a < -90 || a > 85) return -1;
  return (a + 90) / kSectorDegrees;
}

}  // namespace robuter::ptu
