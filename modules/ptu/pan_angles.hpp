// SPDX-License-Identifier: GPL-3.0-or-later
// Pan positions to angles and to the 72 five-degree sectors, as seed 002's ptu.c computes them.
#pragma once

#include <cstdint>

namespace robuter::ptu {

inline constexpr int kSectors = 72;         // 5° sectors around the robot (seed MAX_PTU_SENS)
inline constexpr int kHalfSectors = 36;     // sectors one transducer covers in a pass (180°)
inline constexpr int kSectorDegrees = 5;    // width of a sector, degrees

// Degrees of a pan position the seed's way: pos·185/3600, integer division (truncation towards
// zero, as C), so −1755 → −90 and 1655 → 85.
int position_to_degrees(std::int32_t position);

// The sector the transducer that looks along angle + 90° fills when the pan angle is `degrees`
// (whole degrees): the seed rounds an angle ending in 4/9 or 1/6 one degree away from / towards
// the nearest multiple of 5 ("±1°"), then stores at (angle + 90) / 5. Returns 0..35, or −1 when
// the angle is not within 1° of a multiple of 5 or falls outside −90..85°.
int sector_of_degrees(int degrees);

// The pan angle of a position without truncation, degrees (pos·185/3600 = 0.0514° a position).
double position_to_angle(double position);

// The firmware's firing rule: the sector (0..35) of the multiple of 5° nearest to `degrees` when
// within `tolerance_deg` of it and inside −90..85°, else −1. The seed's whole-degree rule above
// fires within a 3°-wide window that truncation shifts by up to 1° (−71.9° counted as −70°); the
// same 3° window centred (tolerance 1.5°) keeps every sector at 1500 positions/s (2.3° per 30 ms
// activation) and halves the worst angle error.
int sector_near(double degrees, double tolerance_deg);

// The sector of the opposite transducer: the same index plus 36 (seed pt_values[pos + 36]).
constexpr int opposite_sector(int sector) { return sector + kHalfSectors; }

// Sector index brought into 0..71 (negative and large values wrap around the circle).
constexpr int wrap_sector(int sector) {
  const int s = sector % kSectors;
  return s < 0 ? s + kSectors : s;
}

}  // namespace robuter::ptu
