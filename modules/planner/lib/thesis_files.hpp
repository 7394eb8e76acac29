// SPDX-License-Identifier: GPL-3.0-or-later
// Seed 000's input files (annex 1): the parameter file and the environment description file.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "modules/planner/lib/geometry.hpp"
#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/planner/lib/result.hpp"

namespace robuter::plan {

// The parameter file: five lines, numbers separated by white space.
struct ThesisParameters {
  double radius = 0.0;       // m, robot radius (obstacles are expanded by it)
  double speed = 0.0;        // m/s, robot speed
  double heading_deg = 0.0;  // degrees, initial heading in the global frame
  Point2 start;              // m, initial position
  Point2 goal;               // m, goal position
};

// An obstacle polygon of the environment file, vertices in order (either orientation).
struct Polygon {
  std::vector<Point2> vertices;  // m
};

// Why: "radius / speed / heading / x y start / x y goal"; any white-space layout is accepted
// (the thesis reads it with fscanf) but exactly seven numbers must be there.
Result<ThesisParameters> parse_parameters(std::string_view text, const std::string& name);
Result<ThesisParameters> load_parameters(const std::string& path);

// Why: "number of obstacles, then per obstacle its vertex count and one x y line per vertex".
Result<std::vector<Polygon>> parse_environment(std::string_view text, const std::string& name);
Result<std::vector<Polygon>> load_environment(const std::string& path);

// Why: the thesis marks polygon edges (Bresenham, edge by edge, closing edge included) as
// obstacle cells; expansion by the robot is done later by the footprint layers. Parts outside
// the map are clipped.
void rasterise_polygons(OccupancyMap& map, const std::vector<Polygon>& polygons);

}  // namespace robuter::plan
