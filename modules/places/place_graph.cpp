// SPDX-License-Identifier: GPL-3.0-or-later
// Places and doors: lookup by name, point-in-polygon localisation, the polygon predicates.
#include "modules/places/place_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hal/sim/geometry.hpp"

namespace robuter::places {

namespace {

constexpr double kOnEdge = 1e-3;  // m: a point this close to an edge is on it

// Why: 2-D cross product of (b - a) and (c - a).
double cross(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 u = b - a, v = c - a;
  return u.x() * v.y() - u.y() * v.x();
}

}  // namespace

PlaceGraph::PlaceGraph(std::vector<Place> places, std::vector<Door> doors)
    : places_(std::move(places)), doors_(std::move(doors)), doors_of_(places_.size()) {
  for (std::size_t d = 0; d < doors_.size(); ++d) {
    doors_of_[doors_[d].a].push_back(d);
    doors_of_[doors_[d].b].push_back(d);
  }
}

std::optional<std::size_t> PlaceGraph::find(std::string_view name) const {
  for (std::size_t i = 0; i < places_.size(); ++i)
    if (places_[i].name == name) return i;
  return std::nullopt;
}

std::optional<std::size_t> PlaceGraph::place_at(const Vec2& point) const {
  for (std::size_t i = 0; i < places_.size(); ++i)
    if (inside_polygon(places_[i].area, point)) return i;
  return std::nullopt;
}

bool inside_polygon(const std::vector<Vec2>& polygon, const Vec2& p) {
  if (polygon.size() < 3) return false;
  if (distance_to_boundary(polygon, p) <= kOnEdge) return true;
  return sim::point_in_polygon(p, polygon);  // even-odd; the boundary was decided above
}

double distance_to_boundary(const std::vector<Vec2>& polygon, const Vec2& p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    best = std::min(best, sim::point_segment_distance(p, polygon[j], polygon[i]));
  return best;
}

double signed_area(const std::vector<Vec2>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    twice += polygon[j].x() * polygon[i].y() - polygon[i].x() * polygon[j].y();
  return 0.5 * twice;
}

bool segments_cross(const Vec2& p1, const Vec2& p2, const Vec2& q1, const Vec2& q2) {
  constexpr double eps = 1e-9;
  const double d1 = cross(q1, q2, p1), d2 = cross(q1, q2, p2);
  const double d3 = cross(p1, p2, q1), d4 = cross(p1, p2, q2);
  return ((d1 > eps && d2 < -eps) || (d1 < -eps && d2 > eps)) &&
         ((d3 > eps && d4 < -eps) || (d3 < -eps && d4 > eps));
}

bool valid_name(std::string_view name) {
  if (name.empty() || name.size() > 15) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
  });
}

}  // namespace robuter::places
