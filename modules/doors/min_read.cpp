// SPDX-License-Identifier: GPL-3.0-or-later
// init_doors()'s table and its continuous twin.
#include "modules/doors/min_read.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace robuter::doors {

SideDistances side_distances(const BodyGeometry& g) {
  const std::int32_t half_box = g.box_width_mm / 2;
  return {g.pan_x_mm - half_box + g.safety_mm, g.length_mm - g.pan_x_mm - half_box + g.safety_mm,
          g.pan_y_mm - half_box + g.safety_mm, g.width_mm - g.pan_y_mm - half_box + g.safety_mm};
}

namespace {
constexpr double kSectorRad = 5.0 * std::numbers::pi / 180.0;  // one sector, rad
// x / cos(k·5°) or x / sin(k·5°), truncated as the seed's assignment to long.
std::int32_t over_cos(std::int32_t x, int k) { return static_cast<std::int32_t>(x / std::cos(kSectorRad * k)); }
std::int32_t over_sin(std::int32_t x, int k) { return static_cast<std::int32_t>(x / std::sin(kSectorRad * k)); }
}  // namespace

// The seed's loops, range by range, with its own index arithmetic.
MinReadTable min_read_table(const BodyGeometry& g) {
  const SideDistances s = side_distances(g);
  MinReadTable t{};
  auto at = [&](int i) -> std::int32_t& { return t[static_cast<std::size_t>(i)]; };
  at(0) = s.front;
  at(36) = s.rear;
  for (int i = 1; i <= 5; ++i) at(i) = over_cos(s.front, i);
  for (int i = 6; i <= 18; ++i) at(i) = over_sin(s.left, i);
  for (int i = 19; i <= 27; ++i) at(i) = over_sin(s.left, 36 - i);
  for (int i = 28; i <= 35; ++i) at(i) = over_cos(s.rear, 36 - i);
  for (int i = 37; i <= 45; ++i) at(i) = over_cos(s.rear, i - 36);
  for (int i = 46; i <= 54; ++i) at(i) = over_sin(s.right, i - 36);
  for (int i = 55; i <= 66; ++i) at(i) = over_sin(s.right, 72 - i);
  for (int i = 67; i <= 71; ++i) at(i) = over_cos(s.front, 72 - i);
  return t;
}

// Why the minimum: a ray from inside a rectangle leaves it through the first side it meets.
double min_read_at(const SideDistances& s, double a) {
  const double c = std::cos(a), sn = std::sin(a);
  const double along = c >= 0.0 ? s.front : s.rear;   // front or rear side, mm
  const double across = sn >= 0.0 ? s.left : s.right; // left or right side, mm
  double best = 1e9;
  if (std::abs(c) > 1e-9) best = along / std::abs(c);
  if (std::abs(sn) > 1e-9) best = std::min(best, across / std::abs(sn));
  return best;
}

// Why corners: the boundary rises to each corner of the rectangle and falls past it, so its
// maximum over an interval is at an end or at a corner inside.
double min_read_max(const SideDistances& s, double lo, double hi) {
  double best = std::max(min_read_at(s, lo), min_read_at(s, hi));
  const double corners[] = {std::atan2(s.left, s.front), std::atan2(s.left, -s.rear), std::atan2(-s.right, -s.rear),
                            std::atan2(-s.right, s.front)};
  for (double c : corners)
    for (double k = -1.0; k <= 1.0; k += 1.0) {
      const double a = c + k * 2.0 * std::numbers::pi;
      if (a > lo && a < hi) best = std::max(best, min_read_at(s, a));
    }
  return best;
}

}  // namespace robuter::doors
