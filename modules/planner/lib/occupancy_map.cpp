// SPDX-License-Identifier: GPL-3.0-or-later
// The occupancy grid: counts, beam integration (seed 003) and the change log.
#include "modules/planner/lib/occupancy_map.hpp"

#include <algorithm>
#include <cmath>

#include "modules/planner/lib/bresenham.hpp"

namespace robuter::plan {

// Why: Liang-Barsky clip of a segment to the map grown by one cell, so edges far outside the
// map cost nothing; segments inside are returned unchanged (same Bresenham cells).
bool clip_segment_to_map(const MapGeometry& g, Point2& p, Point2& q) {
  const double x0 = g.origin.x - g.resolution, x1 = g.origin.x + (g.width + 1) * g.resolution;
  const double y0 = g.origin.y - g.resolution, y1 = g.origin.y + (g.height + 1) * g.resolution;
  double t0 = 0.0, t1 = 1.0;
  const double dx = q.x - p.x, dy = q.y - p.y;
  const double pk[4] = {-dx, dx, -dy, dy};
  const double qk[4] = {p.x - x0, x1 - p.x, p.y - y0, y1 - p.y};
  for (int i = 0; i < 4; ++i) {
    if (pk[i] == 0.0) {
      if (qk[i] < 0.0) return false;
      continue;
    }
    const double t = qk[i] / pk[i];
    if (pk[i] < 0.0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  const Point2 a{p.x + t0 * dx, p.y + t0 * dy};
  const Point2 b{p.x + t1 * dx, p.y + t1 * dy};
  if (t0 > 0.0) p = a;
  if (t1 < 1.0) q = b;
  return true;
}

// Why: every buffer is sized once here so that later updates never allocate.
OccupancyMap::OccupancyMap(const MapGeometry& geometry, std::uint8_t threshold, std::uint8_t initial)
    : geo_(geometry), threshold_(std::max<std::uint8_t>(threshold, 1)), initial_(std::min(initial, kMaxCount)) {
  geo_.width = std::max(geo_.width, 1);
  geo_.height = std::max(geo_.height, 1);
  const auto n = static_cast<std::size_t>(geo_.width) * static_cast<std::size_t>(geo_.height);
  counts_.assign(n, kUnknown);
  logged_.assign(n, 0);
  changes_.reserve(n);
}

// Why: world to grid is a floor, as the thesis' pto_mapa() for positive coordinates.
// Far-away or non-finite points are clamped to a cell far outside (never a wrapped int).
Cell OccupancyMap::cell_of(Point2 p) const {
  auto axis = [&](double v, double o) {
    const double c = std::floor((v - o) / geo_.resolution);
    if (!(c > -1e9)) return -1'000'000'000;  // also NaN
    if (c > 1e9) return 1'000'000'000;
    return static_cast<int>(c);
  };
  return {axis(p.x, geo_.origin.x), axis(p.y, geo_.origin.y)};
}

// Why: paths are handed to the controller as cell centres (the thesis adds PRECISAO/2).
Point2 OccupancyMap::center(Cell c) const {
  return {geo_.origin.x + (c.x + 0.5) * geo_.resolution,
          geo_.origin.y + (c.y + 0.5) * geo_.resolution};
}

// Why: the single write path keeps the change log exact.
void OccupancyMap::write(std::uint32_t i, std::uint8_t n) {
  const std::uint8_t old = counts_[i];
  if (old == n) return;
  counts_[i] = n;
  if (state_of(old) != state_of(n) && !logged_[i]) {
    logged_[i] = 1;
    changes_.push_back(i);
  }
}

void OccupancyMap::set_count(Cell c, std::uint8_t n) {
  if (contains(c)) write(index(c), n);
}

void OccupancyMap::mark_occupied(Cell c) {
  if (!contains(c)) return;
  const std::uint32_t i = index(c);
  const std::uint8_t n = counts_[i];
  if (n == kUnknown || n < threshold_) write(i, threshold_);
}

void OccupancyMap::mark_free(Cell c) {
  if (contains(c)) write(index(c), 0);
}

void OccupancyMap::clear() {
  for (std::uint32_t i = 0; i < counts_.size(); ++i) write(i, kUnknown);
}

void OccupancyMap::shift(int dx, int dy) {
  clear_changes();
  const int w = geo_.width, h = geo_.height;
  geo_.origin.x += dx * geo_.resolution;
  geo_.origin.y += dy * geo_.resolution;
  // New cell (x, y) is old cell (x + dx, y + dy); rows and columns are walked away from the
  // side they are read from, so every count is read before it is overwritten.
  const int y_first = dy >= 0 ? 0 : h - 1, y_step = dy >= 0 ? 1 : -1;
  const int x_first = dx >= 0 ? 0 : w - 1, x_step = dx >= 0 ? 1 : -1;
  for (int n = 0, y = y_first; n < h; ++n, y += y_step) {
    for (int m = 0, x = x_first; m < w; ++m, x += x_step) {
      const Cell from{x + dx, y + dy};
      counts_[index({x, y})] = contains(from) ? counts_[index(from)] : kUnknown;
    }
  }
}

// Why: seed 003's update rule; the beam is walked cell to cell with Bresenham like the thesis.
void OccupancyMap::integrate_beam(Point2 origin, double angle, double range, double max_range) {
  if (!(range >= 0.0) || !(max_range > 0.0)) return;  // also rejects NaN
  if (!std::isfinite(origin.x) || !std::isfinite(origin.y) || !std::isfinite(angle)) return;
  bool hit = range < max_range;
  const double len = std::min(range, max_range);
  Point2 end{origin.x + len * std::cos(angle), origin.y + len * std::sin(angle)};
  Point2 from = origin;
  const Point2 full_end = end;
  if (!clip_segment_to_map(geo_, from, end)) return;  // the beam misses the map
  const bool clipped_end = end.x != full_end.x || end.y != full_end.y;
  if (clipped_end) hit = false;                        // the hit cell is outside the map
  const Cell a = cell_of(from);
  const Cell b = cell_of(end);
  for_each_line_cell(a, b, [&](int x, int y) {
    const Cell c{x, y};
    const bool last = x == b.x && y == b.y;
    if (!contains(c)) return !last;  // clipped; keep walking until the end
    const std::uint32_t i = index(c);
    const std::uint8_t n = counts_[i] == kUnknown ? initial_ : counts_[i];
    if (last && hit) {
      write(i, static_cast<std::uint8_t>(std::min<int>(n + 1, kMaxCount)));
    } else {
      write(i, n == 0 ? std::uint8_t{0} : static_cast<std::uint8_t>(n - 1));
    }
    return true;
  });
}

void OccupancyMap::clear_changes() {
  for (std::uint32_t i : changes_) logged_[i] = 0;
  changes_.clear();
}

}  // namespace robuter::plan
