// SPDX-License-Identifier: GPL-3.0-or-later
// Cell masks of discs and of rectangles swept over heading intervals.
#include "modules/planner/lib/footprint.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "modules/planner/lib/geometry.hpp"

namespace robuter::plan {
namespace {

// Why: masks are built from a predicate over a bounding square of offsets, row by row, into
// runs (a row may hold several runs for shapes that are not convex).
template <class Meets>
FootprintMask mask_from(int reach, Meets&& meets) {
  FootprintMask m;
  for (int dy = -reach; dy <= reach; ++dy) {
    int dx = -reach;
    while (dx <= reach) {
      while (dx <= reach && !meets(dx, dy)) ++dx;
      if (dx > reach) break;
      const int lo = dx;
      while (dx <= reach && meets(dx, dy)) ++dx;
      m.runs.push_back({dy, lo, dx - 1});
    }
  }
  return m;
}

// Why: separating-axis test of the unit cell square centred at (sx, sy) against a rectangle
// with centre (cx, cy), unit axis (ux, uy) and half extents a (along) and b (across); cell units.
bool square_meets_rectangle(double sx, double sy, double cx, double cy, double ux, double uy,
                            double a, double b) {
  const double vx = -uy, vy = ux;
  const double ex = sx - cx, ey = sy - cy;
  if (std::fabs(ex) >= a * std::fabs(ux) + b * std::fabs(vx) + 0.5) return false;
  if (std::fabs(ey) >= a * std::fabs(uy) + b * std::fabs(vy) + 0.5) return false;
  if (std::fabs(ex * ux + ey * uy) >= a + 0.5 * (std::fabs(ux) + std::fabs(uy))) return false;
  if (std::fabs(ex * vx + ey * vy) >= b + 0.5 * (std::fabs(vx) + std::fabs(vy))) return false;
  return true;
}

}  // namespace

FootprintMask disc_mask(double radius, double resolution) {
  const double r = std::max(radius, 0.0) / resolution;
  const int reach = static_cast<int>(std::ceil(r + 0.5));
  return mask_from(reach, [r](int dx, int dy) {
    if (dx == 0 && dy == 0) return true;
    const double ex = std::max(std::abs(dx) - 0.5, 0.0);
    const double ey = std::max(std::abs(dy) - 0.5, 0.0);
    return ex * ex + ey * ey < r * r;
  });
}

FootprintMask rectangle_mask(const RectangleFootprint& rect, double resolution, double heading_lo,
                             double heading_hi) {
  const double a0 = (0.5 * rect.length + rect.margin) / resolution;
  const double b0 = (0.5 * rect.width + rect.margin) / resolution;
  const double off = rect.center_offset / resolution;
  const double radius = std::hypot(std::fabs(off) + a0, b0);
  const double span = std::max(heading_hi - heading_lo, 0.0);
  const double max_step = 0.5 * kPi / 180.0;
  const int samples = static_cast<int>(std::ceil(span / max_step)) + 1;
  const double step = samples > 1 ? span / (samples - 1) : 0.0;
  const double grow = radius * 0.5 * step;  // largest displacement to the nearest sample
  const double a = a0 + grow, b = b0 + grow;
  const int reach = static_cast<int>(std::ceil(radius + grow + 1.0));
  // Mark the cells met at each sampled heading (trigonometry once per sample), then read runs.
  const int side = 2 * reach + 1;
  std::vector<std::uint8_t> met(static_cast<std::size_t>(side) * static_cast<std::size_t>(side), 0);
  for (int i = 0; i < samples; ++i) {
    const double th = heading_lo + step * i;
    const double c = std::cos(th), sn = std::sin(th);
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dx = -reach; dx <= reach; ++dx) {
        std::uint8_t& cell = met[static_cast<std::size_t>((dy + reach) * side + (dx + reach))];
        if (!cell && square_meets_rectangle(dx, dy, off * c, off * sn, c, sn, a, b)) cell = 1;
      }
  }
  return mask_from(reach, [&](int dx, int dy) {
    return (dx == 0 && dy == 0) || met[static_cast<std::size_t>((dy + reach) * side + (dx + reach))] != 0;
  });
}

double slice_heading(int slice, int slices) { return slice * 2.0 * kPi / slices; }

int slice_of_heading(double heading, int slices) {
  const double w = wrap_angle(heading, 2.0 * kPi);
  const int k = static_cast<int>(std::lround(w / (2.0 * kPi / slices)));
  return k % slices;
}

std::vector<FootprintMask> rectangle_slices(const RectangleFootprint& rect, double resolution,
                                            int slices) {
  std::vector<FootprintMask> out;
  const double half = kPi / slices;
  for (int k = 0; k < slices; ++k) {
    const double c = slice_heading(k, slices);
    out.push_back(rectangle_mask(rect, resolution, c - half, c + half));
  }
  return out;
}

double circumscribed_radius(const RectangleFootprint& rect) {
  return std::hypot(0.5 * rect.length + std::fabs(rect.center_offset) + rect.margin,
                    0.5 * rect.width + rect.margin);
}

double inscribed_radius(const RectangleFootprint& rect) {
  const double along = 0.5 * rect.length - std::fabs(rect.center_offset);
  return std::max(0.0, std::min(along, 0.5 * rect.width) + rect.margin);
}

}  // namespace robuter::plan
