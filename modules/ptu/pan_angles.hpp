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

// The sector of the opposite transducer: the same index plus 36 (seed pt_values[pos + 36]).
constexpr int opposite_sector(int sector) { return sector + kHalfSectors; }

// Sector index brought into 0..71 (negative and large values wrap around the circle).
constexpr int wrap_sector(int sector) {
  const int s = sector % kSectors;
  return s < 0 ? s + kSectors : s;
}

}  // namespace robuter::ptu
