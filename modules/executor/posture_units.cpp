// SPDX-License-Identifier: GPL-3.0-or-later
// Posture unit conversions.
#include "modules/executor/posture_units.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace robuter::executor {

// The protocol's theta range is (−180°, 180°]: −180° is reported as +180°.
std::int32_t wrap_centideg(std::int64_t a) {
  a %= kFullTurn;
  if (a <= -kHalfTurn) a += kFullTurn;
  if (a > kHalfTurn) a -= kFullTurn;
  return static_cast<std::int32_t>(a);
}

// Odometry far beyond ±214 km is not a posture; clamping keeps the conversion defined.
std::int32_t metres_to_tenth_mm(double m) {
  const double v = std::round(m * 10'000.0);
  if (!(v == v)) return 0;  // NaN
  constexpr double lo = std::numeric_limits<std::int32_t>::min(), hi = std::numeric_limits<std::int32_t>::max();
  return static_cast<std::int32_t>(v < lo ? lo : (v > hi ? hi : v));
}

// Rounded to the nearest 0.01°, then wrapped.
std::int32_t radians_to_centideg(double rad) {
  if (!(rad == rad) || std::abs(rad) > 1e6) return 0;
  return wrap_centideg(static_cast<std::int64_t>(std::llround(rad * kHalfTurn / std::numbers::pi)));
}

double tenth_mm_to_metres(std::int32_t v) { return static_cast<double>(v) / 10'000.0; }

double centideg_to_radians(std::int32_t a) { return static_cast<double>(a) * std::numbers::pi / kHalfTurn; }

PostureUnits to_posture(const hal::Odometry& o) {
  return {metres_to_tenth_mm(o.x_m), metres_to_tenth_mm(o.y_m), radians_to_centideg(o.theta_rad)};
}

hal::Odometry to_odometry(const PostureUnits& p) {
  return {tenth_mm_to_metres(p.x), tenth_mm_to_metres(p.y), centideg_to_radians(wrap_centideg(p.theta))};
}

}  // namespace robuter::executor
