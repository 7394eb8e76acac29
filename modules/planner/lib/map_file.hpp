// SPDX-License-Identifier: GPL-3.0-or-later
// The planner's own saved-map format ("robuter-map 1"): header lines, then hex counts per cell.
#pragma once

#include <string>
#include <string_view>

#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/planner/lib/result.hpp"

namespace robuter::plan {

// Format (text, '\n' or "\r\n" line ends):
//   robuter-map 1
//   width W            cells
//   height H           cells
//   resolution R       m per cell
//   origin X Y         m, lower-left corner of cell (0, 0)
//   threshold T        hits for an obstacle (1..254)
//   data
//   H lines of 2*W characters, the top row (y = H-1) first: per cell two hex digits (the hit
//   count, 00..fe) or ".." for a never-seen cell.
// Lines after the header keys may come in any order; '#' starts a comment line in the header.

// A saved map's header, and where each key was (1-based lines, 0 when absent).
struct MapHeader {
  MapGeometry geometry;           // cells, m per cell, origin (m)
  int threshold = OccupancyMap::kDefaultThreshold;  // hits for an obstacle in the file's counts
  int width_line = 0;             // line of "width"
  int height_line = 0;            // line of "height"
  int resolution_line = 0;        // line of "resolution"
  int origin_line = 0;            // line of "origin"
  int threshold_line = 0;         // line of "threshold"
  int data_line = 0;              // line of "data"; row y is on line data_line + height - y
};

// Why: text keeps saved maps diffable and readable next to the text rendering.
std::string format_map(const OccupancyMap& map);
// Why: a user of a map file (the firmware's a-priori map) checks its geometry, and names the
// header's lines, before the cells are read.
Result<MapHeader> parse_map_header(std::string_view text, const std::string& name);
Result<OccupancyMap> parse_map(std::string_view text, const std::string& name);

// Why: file wrappers; errors name the file (and line when parsing).
Status save_map(const OccupancyMap& map, const std::string& path);
Result<OccupancyMap> load_map(const std::string& path);

}  // namespace robuter::plan
