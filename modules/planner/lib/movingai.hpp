// SPDX-License-Identifier: GPL-3.0-or-later
// MovingAI grid benchmark files (Sturtevant 2012): .map grids and .scen scenario lists.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "modules/planner/lib/geometry.hpp"
#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/planner/lib/result.hpp"

namespace robuter::plan {

// One MovingAI problem (a .scen line). Cell (x, y) is column x of row y, row 0 first in the file.
struct Scenario {
  int bucket = 0;          // difficulty bucket (first column)
  std::string map;         // map name as written in the file
  int map_width = 0;       // cells
  int map_height = 0;      // cells
  Cell start;              // cells
  Cell goal;               // cells
  double optimal = 0.0;    // cells: published optimal length (last column)
};

// Why: '.', 'G' and 'S' are passable, every other character is not; the result is a map of
// 1-unit cells (free or occupied, nothing unknown) whose cell (x, y) is file row y, column x.
Result<OccupancyMap> parse_movingai_map(std::string_view text, const std::string& name);
Result<OccupancyMap> load_movingai_map(const std::string& path);

// Why: "version N" then one problem a line (9 tab-separated fields); blank lines skipped.
Result<std::vector<Scenario>> parse_movingai_scen(std::string_view text, const std::string& name);
Result<std::vector<Scenario>> load_movingai_scen(const std::string& path);

}  // namespace robuter::plan
