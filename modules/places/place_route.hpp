// SPDX-License-Identifier: GPL-3.0-or-later
// Routes over places: seed 003's dijkstra() from the current place to the user's goal place.
#pragma once

#include <cstddef>
#include <vector>

#include "modules/places/place_graph.hpp"

namespace robuter::places {

// One leg of a route: through a door into the next place.
struct RouteLeg {
  std::size_t door = 0;   // index into PlaceGraph::doors()
  std::size_t place = 0;  // the place entered through it
};

// A route from one place to another; empty legs when from == to.
struct PlaceRoute {
  bool found = false;          // false: no chain of doors joins them
  std::size_t from = 0;        // the start place
  std::vector<RouteLeg> legs;  // in order
  double length = 0.0;         // m: centre -> door -> ... -> door -> centre, straight segments
};

// Why: the shortest route between two places. Seed 003 weighs an edge by the distance between
// the two nodes' centres; here a leg is weighed centre -> door -> centre (a route goes through
// the door, which may be far from the straight line between centres: docs/PLACES.md).
// Ties: fewer legs, then lower door index. `from`, `to` must be valid place indices.
PlaceRoute shortest_route(const PlaceGraph& graph, std::size_t from, std::size_t to);

}  // namespace robuter::places
