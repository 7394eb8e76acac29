// SPDX-License-Identifier: GPL-3.0-or-later
// The place graph's file ("robuter-places 1", TOML): read and checked, one file:line error or a graph.
#pragma once

#include <string>
#include <string_view>

#include "hal/sim/result.hpp"
#include "modules/places/place_graph.hpp"

namespace robuter::places {

// Format (docs/PLACES.md):
//   [places]  format = "robuter-places 1", units = "m" | "cm" | "mm" (default m), world = "…" (optional)
//   [[place]] name, area = [[x, y], …] (>= 3 vertices, simple), centre = [x, y] (inside area)
//   [[door]]  name, between = ["place", "place"], at = [x, y], width
// Checked: every key known; names valid and unique; polygons simple, of non-zero area, stored
// counter-clockwise, not overlapping another place (edges may be shared); a door's places exist
// and differ, its `at` lies within kDoorOnBoundary of both boundaries, 0 < width <= 10 m; at
// least one place. The graph need not be connected (a route between parts is refused).
inline constexpr double kDoorOnBoundary = 0.15;  // m

// Why: a graph from text (`file` names it in errors).
sim::Result<PlaceGraph> parse_place_graph(std::string_view text, std::string_view file);

// Why: a graph from a file (at most 1 MB), errors as "file:line: message".
sim::Result<PlaceGraph> load_place_graph(const std::string& path);

}  // namespace robuter::places
