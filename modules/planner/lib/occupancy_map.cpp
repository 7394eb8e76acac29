// The occupancy grid: counts, beam integration (seed 003) and the change log.
#include "modules/planner/lib/occupancy_map.hpp"

#include <algorithm>
#include <cmath>

#include "modules/planner/lib/bresenham.hpp"

namespace robuter::plan {

// Why: every buffer is sized once here so that later updates never allocate.
OccupancyMap::OccupancyMap(const MapGeometry& geometry, std::uint8_t threshold)
    : geo_(geometry), threshold_(std::max<std::uint8_t>(threshold, 1)) {
  geo_.width = std::max(geo_.width, 1);
  geo_.height = std::max(geo_.height, 1);
  const auto n = static_cast<std::size_t>(geo_.width) * static_cast<std::size_t>(geo_.height);
  counts_.assign(n, kUnknown);
  logged_.assign(n, 0);
  changes_.reserve(n);
}

// Why: world to grid is a floor, as the thesis' pto_mapa() for positive coordinates.
Cell OccupancyMap::cell_of(Point2 p) const {
  return {static_cast<int>(std::floor((p.x - geo_.origin.x) / geo_.resolution)),
          static_cast<int>(std::floor((p.y - geo_.origin.y) / geo_.resolution))};
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

// Why: seed 003's update rule; the beam is walked cell to cell with Bresenham like the thesis.
void OccupancyMap::integrate_beam(Point2 origin, double angle, double range, double max_range) {
  if (!(range >= 0.0) || !(max_range > 0.0)) return;  // also rejects NaN
  const bool hit = range < max_range;
  // A beam never needs to be longer than the map is far from its origin (guards huge ranges).
  const double cx = geo_.origin.x + 0.5 * geo_.width * geo_.resolution;
  const double cy = geo_.origin.y + 0.5 * geo_.height * geo_.resolution;
  const double reach = std::hypot(origin.x - cx, origin.y - cy) +
                       std::hypot(geo_.width, geo_.height) * geo_.resolution;
  const double len = std::min({range, max_range, reach});
  const Point2 end{origin.x + len * std::cos(angle), origin.y + len * std::sin(angle)};
  const Cell a = cell_of(origin);
  const Cell b = cell_of(end);
  for_each_line_cell(a, b, [&](int x, int y) {
    const Cell c{x, y};
    const bool last = x == b.x && y == b.y;
    if (!contains(c)) return !last;  // clipped; keep walking until the end
    const std::uint32_t i = index(c);
    const std::uint8_t n = counts_[i];
    if (last && hit) {
      write(i, n == kUnknown ? std::uint8_t{1}
                             : static_cast<std::uint8_t>(std::min<int>(n + 1, kMaxCount)));
    } else {
      write(i, n == kUnknown || n == 0 ? std::uint8_t{0} : static_cast<std::uint8_t>(n - 1));
    }
    return true;
  });
}

void OccupancyMap::clear_changes() {
  for (std::uint32_t i : changes_) logged_[i] = 0;
  changes_.clear();
}

}  // namespace robuter::plan
