// SPDX-License-Identifier: GPL-3.0-or-later
// Seed 003's topological map: places (area polygon, centre), doors between them, where the robot is.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hal/sim/types.hpp"  // Vec2 (Eigen::Vector2d)

namespace robuter::places {

using Vec2 = sim::Vec2;  // m, in the map's frame

// A place: seed 003's node (`area`, `center`; its `near` list is the doors below).
struct Place {
  std::string name;        // unique; letters, digits, '-', '_'; 1..15 characters
  std::vector<Vec2> area;  // the place's polygon (m), counter-clockwise, simple, >= 3 vertices
  Vec2 centre{0.0, 0.0};   // m, inside `area`: where a route into the place ends
};

// A door joins two places: where it is and how wide (the door crossing or the planner, by width).
struct Door {
  std::string name;   // unique among doors, same characters as a place's
  std::size_t a = 0;  // index of one place
  std::size_t b = 0;  // index of the other (b != a)
  Vec2 at{0.0, 0.0};  // m, the middle of the opening, on the places' shared boundary
  double width = 0.0; // m, the clear opening (> 0)
};

// The whole graph, checked when loaded (place_graph_file.hpp): names unique, centres inside,
// polygons simple and not overlapping, doors on both boundaries. Immutable afterwards.
class PlaceGraph {
 public:
  PlaceGraph() = default;
  PlaceGraph(std::vector<Place> places, std::vector<Door> doors);

  const std::vector<Place>& places() const { return places_; }
  const std::vector<Door>& doors() const { return doors_; }
  // Why: the doors of one place, as indices into doors() (seed 003's `near`, with the door).
  const std::vector<std::size_t>& doors_of(std::size_t place) const { return doors_of_[place]; }

  // Why: a place by its name (the protocol's and the user's handle).
  std::optional<std::size_t> find(std::string_view name) const;

  // Why: localisation in a place (seed 003's placenode() with inside_polygon()): the place whose
  // polygon holds the point; on a shared edge, the first place in file order; none outside all.
  std::optional<std::size_t> place_at(const Vec2& point) const;

 private:
  std::vector<Place> places_;                      // in file order
  std::vector<Door> doors_;                        // in file order
  std::vector<std::vector<std::size_t>> doors_of_; // per place: its doors
};

// Why: seed 003's inside_polygon(): even-odd ray casting; a point on an edge counts as inside
// (within 1 mm), so a point on the shared edge of two places is in both.
bool inside_polygon(const std::vector<Vec2>& polygon, const Vec2& p);

// Why: distance from a point to a polygon's boundary, m (for checks: doors on their places).
double distance_to_boundary(const std::vector<Vec2>& polygon, const Vec2& p);

// Why: the signed area of a polygon, m² (> 0 counter-clockwise).
double signed_area(const std::vector<Vec2>& polygon);

// Why: true when two segments cross at a point inside both (not at shared end points, not along
// a shared line): what makes a polygon not simple, or two places overlap.
bool segments_cross(const Vec2& p1, const Vec2& p2, const Vec2& q1, const Vec2& q2);

// Why: the name rule, in one place.
bool valid_name(std::string_view name);

}  // namespace robuter::places
