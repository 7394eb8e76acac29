// SPDX-License-Identifier: GPL-3.0-or-later
// Seed 003's text picture of a map window: '.' unknown, '#' obstacle, ' ' free, 'P' robot.
#pragma once

#include <optional>
#include <string>

#include "modules/planner/lib/geometry.hpp"
#include "modules/planner/lib/occupancy_map.hpp"

namespace robuter::plan {

// Why: a quick look at the map in logs and terminals. The window is cells [x0, x0 + width) x
// [y0, y0 + height); rows are printed top (largest y) first, one '\n'-terminated line each;
// cells outside the map print as unknown; `robot` (if inside the window) prints as 'P'.
std::string render_text(const OccupancyMap& map, int x0, int y0, int width, int height,
                        std::optional<Cell> robot = std::nullopt);

// Why: the seed's view: a square window of (2 * half + 1) cells centred on the robot.
std::string render_around(const OccupancyMap& map, Cell robot, int half);

}  // namespace robuter::plan
