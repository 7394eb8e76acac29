// SPDX-License-Identifier: GPL-3.0-or-later
// Seed 003's characters for a square window of the map, written into fixed storage (for XM).
#pragma once

#include <span>

#include "modules/planner/lib/geometry.hpp"
#include "modules/planner/lib/occupancy_map.hpp"

namespace robuter::planner {

// Why: the link shows the map around the robot without allocating: `out` holds side × side
// characters, row 0 the top (largest y), each '.' unknown, '#' obstacle, ' ' free, 'P' the
// robot's cell (the centre); cells off the map print '.'. Same characters as render_text().
void render_window(const plan::OccupancyMap& map, plan::Cell center, int side, std::span<char> out);

}  // namespace robuter::planner
