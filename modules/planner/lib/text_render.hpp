// SPDX-License-Identifier: GPL-3.0-or-later
// Seed 003's text picture of a map window: '.' unknown, '#' obstacle, ' ' free, 'P' robot.
#pragma once

#include <optional>
#include <string>

#include "modules/planner/lib/geometry.hpp"
#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/planner/lib/pass_grid.hpp"

namespace robuter::plan {

// Why: a quick look at the map in logs and terminals. The window is cells [x0, x0 + width) x
// [y0, y0 + height); rows are printed top (largest y) first, one '\n'-terminated line each;
// cells outside the map print as unknown; `robot` (if inside the window) prints as 'P'.
std::string render_text(const OccupancyMap& map, int x0, int y0, int width, int height,
                        std::optional<Cell> robot = std::nullopt);

// Why: the seed's view: a square window of (2 * half + 1) cells centred on the robot.
std::string render_around(const OccupancyMap& map, Cell robot, int half);

// Why: seed 000's `gt.log` (docs/PLANNER.md PL-10): the whole expanded map, top row first, 'X'
// where the grid is blocked, ' ' elsewhere, 'O' the start ('M' when the start itself is
// blocked), 'D' the goal; the thesis's map had no unknown cells, so none are shown.
std::string render_thesis_log(const PassGrid& expanded, Cell start, Cell goal);

}  // namespace robuter::plan
