// SPDX-License-Identifier: GPL-3.0-or-later
// The walls a place graph implies (every place edge except its doors), as an occupancy grid.
#pragma once

#include <vector>

#include "modules/places/place_graph.hpp"
#include "modules/planner/lib/occupancy_map.hpp"

namespace robuter::places {

// Why: the place graph as known structure (docs/PLACES.md, "Walls from the place graph"): a
// place's edges are the faces of the walls around it, except where a door opens them. Every
// cell just outside an edge (its wall side) is occupied, apart from each door's opening (a door
// within kDoorOnBoundary (0.15 m) of the edge removes the edge's stretch within width / 2 of it); every other cell
// is unknown. The grid covers the graph's bounding box plus `margin` (m), cells of `resolution`
// (m) aligned on multiples of it (so that a planner window whose origin is a multiple of the
// same resolution shares its cell boundaries).
plan::OccupancyMap wall_raster(const PlaceGraph& graph, double resolution, double margin = 1.0);

// Why: the cells a door keeps open for the planner (docs/PLACES.md, "Walls from the place graph"):
// the centres, on a grid of `resolution` (m) aligned on multiples of it, of the cells whose centre
// lies within the opening (width / 2 along the door's edge, less half a cell) and within `reach`
// (m) of the wall's line on either side, less the cells `walls` (wall_raster of the same graph
// and resolution) holds occupied: where a corridor's open door meets a wall corner, the corner
// stays. The ring's echoes off the jambs would otherwise close the opening.
std::vector<plan::Point2> door_openings(const PlaceGraph& graph, const plan::OccupancyMap& walls,
                                        double reach = 0.35);

}  // namespace robuter::places
