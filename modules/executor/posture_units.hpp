// SPDX-License-Identifier: GPL-3.0-or-later
// Conversions between the drive's odometry (m, rad) and the protocol's posture units (0.1 mm, 0.01°).
#pragma once

#include <cstdint>

#include "hal/api/drive.hpp"

namespace robuter::executor {

inline constexpr std::int32_t kHalfTurn = 18'000;  // 180° in 0.01°
inline constexpr std::int32_t kFullTurn = 36'000;  // 360° in 0.01°

// An angle in 0.01° brought into (−18000, 18000].
std::int32_t wrap_centideg(std::int64_t a);
// Metres to 0.1 mm, rounded and clamped to the int32 range.
std::int32_t metres_to_tenth_mm(double m);
// Radians to 0.01°, rounded and wrapped into (−18000, 18000].
std::int32_t radians_to_centideg(double rad);
// 0.1 mm to metres.
double tenth_mm_to_metres(std::int32_t v);
// 0.01° to radians.
double centideg_to_radians(std::int32_t a);

// A posture in the protocol's units.
struct PostureUnits {
  std::int32_t x = 0;      // 0.1 mm
  std::int32_t y = 0;      // 0.1 mm
  std::int32_t theta = 0;  // 0.01°, (−18000, 18000]
};

// The drive's odometry in the protocol's units.
PostureUnits to_posture(const hal::Odometry& o);
// A posture in the protocol's units as the drive's odometry.
hal::Odometry to_odometry(const PostureUnits& p);

}  // namespace robuter::executor
