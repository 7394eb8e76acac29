// SPDX-License-Identifier: GPL-3.0-or-later
// The route table: shortest_route for every pair of places, turned into via points once.
#include "modules/places/route_table.hpp"

#include <cmath>
#include <limits>

#include "hal/sim/geometry.hpp"
#include "modules/places/place_route.hpp"

namespace robuter::places {
namespace {

ViaPoint to_via(const Vec2& p) {
  return {static_cast<std::int32_t>(std::lround(p.x() * 1e4)), static_cast<std::int32_t>(std::lround(p.y() * 1e4))};
}

}  // namespace

Vec2 door_normal_into(const Place& place, const Door& door) {
  const std::vector<Vec2>& a = place.area;
  double best = std::numeric_limits<double>::infinity();
  Vec2 normal{0.0, 0.0};
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2& p = a[i];
    const Vec2& q = a[(i + 1) % a.size()];
    const double d = sim::point_segment_distance(door.at, p, q);
    const Vec2 e = q - p;
    if (d < best && e.norm() > 0.0) {
      best = d;
      normal = Vec2(-e.y(), e.x()) / e.norm();  // left of the edge: inside a counter-clockwise polygon
    }
  }
  return normal;
}

RouteTable::RouteTable(const PlaceGraph& graph, const ViaRules& rules) : n_(graph.places().size()) {
  entries_.resize(n_ * n_);
  for (std::size_t from = 0; from < n_; ++from)
    for (std::size_t to = 0; to < n_; ++to) {
      const PlaceRoute r = shortest_route(graph, from, to);
      Entry& e = entries_[from * n_ + to];
      if (!r.found) continue;
      std::vector<ViaPoint> pts;
      for (const RouteLeg& leg : r.legs) {
        const Door& d = graph.doors()[leg.door];
        if (d.width >= rules.wide_door) {
          pts.push_back(to_via(d.at));
          continue;
        }
        const Vec2 n = door_normal_into(graph.places()[leg.place], d);
        ViaPoint before = to_via(d.at - rules.before * n);
        before.has_theta = true;
        before.theta = static_cast<std::int32_t>(std::lround(std::atan2(n.y(), n.x()) * 18000.0 / M_PI));
        if (before.theta <= -18000) before.theta += 36000;
        pts.push_back(before);
        pts.push_back(to_via(d.at + rules.after * n));
      }
      pts.push_back(to_via(graph.places()[to].centre));
      if (pts.size() > kMaxPoints) continue;
      e.found = true;
      e.first = points_.size();
      e.count = pts.size();
      e.doors = r.legs.size();
      e.length = r.length;
      points_.insert(points_.end(), pts.begin(), pts.end());
    }
}

std::span<const ViaPoint> RouteTable::points(std::size_t from, std::size_t to) const {
  const Entry& e = entry(from, to);
  return {points_.data() + e.first, e.count};
}

}  // namespace robuter::places
