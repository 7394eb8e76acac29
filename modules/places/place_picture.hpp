// SPDX-License-Identifier: GPL-3.0-or-later
// The place graph drawn over a world picture: places, centres, doors, and a route over them.
#pragma once

#include <vector>

#include "hal/sim/render.hpp"
#include "modules/places/place_graph.hpp"
#include "modules/places/place_grid.hpp"
#include "modules/places/place_route.hpp"

namespace robuter::places {

// Why: a scene's overlay that draws `graph` (each place's area tinted and outlined, its centre
// and name, each door as a dot joined to both centres) and, when given, `route` on top (thick,
// from its start place's centre through each door to the goal place's centre). Both must outlive
// the rendering.
sim::DrawHook place_graph_overlay(const PlaceGraph& graph, const PlaceRoute* route = nullptr);

// Why: the legend entries for what place_graph_overlay() draws.
std::vector<picture::Ink> place_graph_keys(bool with_route);

// Why: a scene's overlay that draws place grids (seed 003's grid per place, place_grid.hpp) at
// their place: obstacles dark, free cells light, unknown left as it is, the robot's 'P' a ring;
// then `then` (the place graph's overlay, or empty) over them. The grids must outlive the rendering.
sim::DrawHook place_grids_overlay(const std::vector<PlaceGrid>& grids, sim::DrawHook then = {});

// Why: the legend entries for what place_grids_overlay() draws.
std::vector<picture::Ink> place_grid_keys();

}  // namespace robuter::places
