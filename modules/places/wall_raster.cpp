// SPDX-License-Identifier: GPL-3.0-or-later
// Rasterising a place graph's walls: its places' edges minus the doors' openings.
#include "modules/places/wall_raster.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "hal/sim/geometry.hpp"
#include "modules/places/place_graph_file.hpp"
#include "modules/places/route_table.hpp"

namespace robuter::places {

plan::OccupancyMap wall_raster(const PlaceGraph& graph, double resolution, double margin) {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const Place& p : graph.places())
    for (const Vec2& v : p.area) {
      x0 = std::min(x0, v.x());
      y0 = std::min(y0, v.y());
      x1 = std::max(x1, v.x());
      y1 = std::max(y1, v.y());
    }
  const double ox = std::floor((x0 - margin) / resolution) * resolution;
  const double oy = std::floor((y0 - margin) / resolution) * resolution;
  const int w = static_cast<int>(std::ceil((x1 + margin - ox) / resolution));
  const int h = static_cast<int>(std::ceil((y1 + margin - oy) / resolution));
  plan::OccupancyMap map(plan::MapGeometry{w, h, resolution, {ox, oy}});
  const double step = resolution / 4.0;
  const double outward = std::min(0.01, resolution / 4.0);  // m: a sample pushed to the wall's side
  for (const Place& p : graph.places()) {
    const std::size_t n = p.area.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 a = p.area[i], b = p.area[(i + 1) % n];
      const double len = (b - a).norm();
      if (len <= 0.0) continue;
      const Vec2 dir = (b - a) / len;
      const Vec2 out(dir.y(), -dir.x());  // right of a counter-clockwise edge: outside the place
      // The edge's stretches opened by doors, as [t0, t1] along it (m).
      std::vector<std::pair<double, double>> open;
      for (const Door& d : graph.doors())
        if (sim::point_segment_distance(d.at, a, b) <= kDoorOnBoundary) {  // the file's own rule
          const double t = (d.at - a).dot(dir);
          open.emplace_back(t - d.width / 2.0, t + d.width / 2.0);
        }
      for (double t = 0.0; t <= len; t += step) {
        bool opened = false;
        // A sample on the opening's edge would mark the cell inside it (the edge is a cell
        // boundary when the door is aligned on the grid): the edges count as open.
        for (const auto& [t0, t1] : open) opened = opened || (t > t0 - 1e-6 && t < t1 + 1e-6);
        if (opened) continue;
        const Vec2 q = a + t * dir + outward * out;
        const plan::Cell c = map.cell_of({q.x(), q.y()});
        if (map.contains(c)) map.mark_occupied(c);
      }
    }
  }
  map.clear_changes();
  return map;
}

std::vector<plan::Point2> door_openings(const PlaceGraph& graph, const plan::OccupancyMap& walls, double reach) {
  const double resolution = walls.resolution();
  std::vector<plan::Point2> out;
  for (const Door& d : graph.doors()) {
    const Vec2 n = door_normal_into(graph.places()[d.b], d);
    const Vec2 along(-n.y(), n.x());
    const double half = d.width / 2.0 - resolution / 2.0;
    const double r = std::max(half, reach) + resolution;
    // Every cell centre of the box around the door, kept when inside the opening's rectangle.
    const int i0 = static_cast<int>(std::floor((d.at.x() - r) / resolution));
    const int i1 = static_cast<int>(std::ceil((d.at.x() + r) / resolution));
    const int j0 = static_cast<int>(std::floor((d.at.y() - r) / resolution));
    const int j1 = static_cast<int>(std::ceil((d.at.y() + r) / resolution));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const Vec2 c((i + 0.5) * resolution, (j + 0.5) * resolution);
        const Vec2 v = c - d.at;
        if (std::abs(v.dot(along)) > half || std::abs(v.dot(n)) > reach) continue;
        const plan::Cell w = walls.cell_of({c.x(), c.y()});
        if (walls.contains(w) && walls.state(w) == plan::CellState::Occupied) continue;
        out.push_back({c.x(), c.y()});
      }
  }
  return out;
}

}  // namespace robuter::places
