// SPDX-License-Identifier: GPL-3.0-or-later
// Dijkstra over the place graph (a few dozen places: a linear scan for the next node is enough).
#include "modules/places/place_route.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace robuter::places {

PlaceRoute shortest_route(const PlaceGraph& graph, std::size_t from, std::size_t to) {
  const std::vector<Place>& places = graph.places();
  const std::vector<Door>& doors = graph.doors();
  const std::size_t n = places.size();
  constexpr double inf = std::numeric_limits<double>::infinity();
  PlaceRoute route;
  route.from = from;
  if (from >= n || to >= n) return route;
  // Seed 003's value, prev and read, per place; plus the legs count for ties.
  std::vector<double> value(n, inf);
  std::vector<std::size_t> legs(n, 0);
  std::vector<std::size_t> prev_door(n, doors.size());
  std::vector<bool> read(n, false);
  value[from] = 0.0;
  for (;;) {
    std::size_t u = n;
    for (std::size_t i = 0; i < n; ++i)
      if (!read[i] && value[i] < inf && (u == n || value[i] < value[u] || (value[i] == value[u] && legs[i] < legs[u])))
        u = i;
    if (u == n || u == to) break;
    read[u] = true;
    for (const std::size_t d : graph.doors_of(u)) {
      const Door& door = doors[d];
      const std::size_t v = door.a == u ? door.b : door.a;
      if (read[v]) continue;
      const double w = (places[u].centre - door.at).norm() + (door.at - places[v].centre).norm();
      const double nv = value[u] + w;
      if (nv < value[v] - 1e-9 || (std::abs(nv - value[v]) <= 1e-9 && legs[u] + 1 < legs[v])) {
        value[v] = nv;
        legs[v] = legs[u] + 1;
        prev_door[v] = d;
      }
    }
  }
  if (value[to] == inf) return route;
  route.found = true;
  route.length = value[to];
  for (std::size_t v = to; v != from;) {
    const Door& door = doors[prev_door[v]];
    route.legs.push_back({prev_door[v], v});
    v = door.a == v ? door.b : door.a;
  }
  std::reverse(route.legs.begin(), route.legs.end());
  return route;
}

}  // namespace robuter::places
