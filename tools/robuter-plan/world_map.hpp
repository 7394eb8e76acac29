// SPDX-License-Identifier: GPL-3.0-or-later
// The project's world files (worlds/*.toml, or seed 000 .env through the simulator's loader) as planner maps.
#pragma once

#include <optional>
#include <string>

#include "hal/sim/world.hpp"
#include "modules/planner/lib/geometry.hpp"
#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/planner/lib/result.hpp"

namespace robuter::plan::tool {

// A world as the planner sees it: its obstacle edges in a map, and the file's start and goal.
struct WorldMap {
  OccupancyMap map;             // edges occupied, the rest unknown (as the thesis' files)
  std::optional<Pose2> start;   // m, rad: the world's [start], if any
  std::optional<Point2> goal;   // m: the world's [goal], if any
};

// Why: the planner library reads no simulator format; the tool and the tests rasterise a loaded
// world's obstacle edges (Bresenham, as the thesis' environment files) into `map`; edges off the
// map are clipped cell by cell.
void rasterise_world(const sim::World& world, OccupancyMap& map);

// Why: `robuter-plan -w FILE`: loads the world (errors name file and line, nothing else is
// touched) into a map covering its obstacles plus `margin` m all round, at `resolution` m.
Result<WorldMap> load_world_map(const std::string& path, double resolution, double margin = 0.5);

}  // namespace robuter::plan::tool
