// SPDX-License-Identifier: GPL-3.0-or-later
// The place graph drawn over a world picture: places, centres, doors, and a route over them.
#pragma once

#include <vector>

#include "hal/sim/render.hpp"
#include "modules/places/place_graph.hpp"
#include "modules/places/place_route.hpp"

namespace robuter::places {

// Why: a scene's overlay that draws `graph` (each place's area tinted and outlined, its centre
// and name, each door as a dot joined to both centres) and, when given, `route` on top (thick,
// from its start place's centre through each door to the goal place's centre). Both must outlive
// the rendering.
sim::DrawHook place_graph_overlay(const PlaceGraph& graph, const PlaceRoute* route = nullptr);

// Why: the legend entries for what place_graph_overlay() draws.
std::vector<picture::Ink> place_graph_keys(bool with_route);

}  // namespace robuter::places
