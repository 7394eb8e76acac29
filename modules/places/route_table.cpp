// SPDX-License-Identifier: GPL-3.0-or-later
// The route table: shortest_route for every pair of places, turned into via points once.
#include "modules/places/route_table.hpp"

#include <cmath>
#include <limits>

#include "hal/sim/geometry.hpp"
#include "modules/places/place_route.hpp"

namespace robuter::places {
namespace {

// m between two points (0.1 mm each).
double distance(const ViaPoint& a, const ViaPoint& b) {
  return std::hypot(static_cast<double>(a.x) - b.x, static_cast<double>(a.y) - b.y) * 1e-4;
}

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

RouteTable::RouteTable(const PlaceGraph& graph, const ViaRules& rules)
    : n_(graph.places().size()), long_leg_(rules.long_leg) {
  for (const Place& p : graph.places()) centres_.push_back(to_via(p.centre));
  for (const Door& d : graph.doors())
    for (const std::size_t into : {d.a, d.b}) {
      Pass pass;
      if (d.width >= rules.wide_door) {
        pass.pts[pass.count++] = to_via(d.at);
      } else {
        const Vec2 n = door_normal_into(graph.places()[into], d);
        ViaPoint before = to_via(d.at - rules.before * n);
        before.has_theta = true;
        before.theta = static_cast<std::int32_t>(std::lround(std::atan2(n.y(), n.x()) * 18000.0 / M_PI));
        if (before.theta <= -18000) before.theta += 36000;
        pass.pts[pass.count++] = before;
        pass.pts[pass.count++] = to_via(d.at + rules.after * n);
      }
      passes_.push_back(pass);
    }
  entries_.resize(n_ * n_);
  std::array<ViaPoint, kMaxPoints> pts{};
  for (std::size_t from = 0; from < n_; ++from)
    for (std::size_t to = 0; to < n_; ++to) {
      const PlaceRoute r = shortest_route(graph, from, to);
      Entry& e = entries_[from * n_ + to];
      if (!r.found) continue;
      e.legs_first = legs_.size();
      e.doors = r.legs.size();
      e.length = r.length;
      for (const RouteLeg& leg : r.legs) {
        const std::size_t pass = 2 * leg.door + (leg.place == graph.doors()[leg.door].b ? 1 : 0);
        legs_.push_back({static_cast<std::uint32_t>(pass), static_cast<std::uint32_t>(leg.place)});
      }
      const std::size_t count = write(from, to, false, pts);
      if (count > kMaxPoints) continue;
      e.found = true;
      e.first = points_.size();
      e.count = count;
      points_.insert(points_.end(), pts.begin(), pts.begin() + static_cast<std::ptrdiff_t>(count));
    }
}

std::size_t RouteTable::write(std::size_t from, std::size_t to, bool explore, std::span<ViaPoint> out) const {
  std::size_t n = 0;
  const auto put = [&](ViaPoint p) {
    if (n < out.size()) out[n] = p;
    ++n;
  };
  const auto spin = [](ViaPoint p) {
    p.spin = true;
    return p;
  };
  if (explore) put(spin(centres_[from]));
  const Entry& e = entry(from, to);
  std::size_t in = from;              // the place the route is in before the next door
  const ViaPoint* last = nullptr;     // the route's last point (null: none yet, the robot)
  for (std::size_t k = 0; k < e.doors; ++k) {
    const LegRef& leg = legs_[e.legs_first + k];
    const Pass& pass = passes_[leg.pass];
    // A long way across a place (a hall with doors at both ends) goes by the place's centre, so
    // that each leg fits the planner's window (the route's length is weighed through it too).
    if (!explore && last != nullptr && distance(*last, pass.pts[0]) > long_leg_) put(centres_[in]);
    for (std::size_t i = 0; i < pass.count; ++i) put(pass.pts[i]);
    last = &pass.pts[pass.count - 1];
    if (explore) put(spin(centres_[leg.place]));
    in = leg.place;
  }
  put(centres_[to]);
  return n;
}

std::size_t RouteTable::explore_points(std::size_t from, std::size_t to, std::span<ViaPoint> out) const {
  if (!found(from, to)) return 0;
  const std::size_t n = write(from, to, true, out);
  return n <= out.size() ? n : 0;
}

std::span<const ViaPoint> RouteTable::points(std::size_t from, std::size_t to) const {
  const Entry& e = entry(from, to);
  return {points_.data() + e.first, e.count};
}

}  // namespace robuter::places
