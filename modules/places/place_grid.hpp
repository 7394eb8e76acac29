// SPDX-License-Identifier: GPL-3.0-or-later
// Seed 003's local grid per place: a place's cells cut from the map, saved and loaded as text.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "modules/places/place_graph.hpp"
#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/planner/lib/result.hpp"

namespace robuter::places {

inline constexpr double kPlaceGridMargin = 0.10;  // m around a place's box: its walls' cells

// One place's local grid (seed 003's drawsec(): the node's area cut from the whole grid). The
// cells of the bounding box of the place's polygon, on the map's cells, in seed 003's states.
struct PlaceGrid {
  std::string place;                        // the place's name (PlaceGraph)
  double cell = 0.05;                       // m, cell side
  plan::Point2 origin{};                    // m, the low-left corner of cell (0, 0), map frame
  int width = 0;                            // cells along x
  int height = 0;                           // cells along y
  std::optional<plan::Cell> scanned_from;   // cell where the robot stood ('P'), if on the grid
  std::vector<plan::CellState> cells;       // row-major from the south row, width x height
  // Why: the state of a cell of this grid (x, y from its low-left corner).
  plan::CellState at(int x, int y) const {
    return cells[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
  }
};

// The cells a place's grid covers on a map's cells.
struct PlaceBox {
  plan::Cell lo{};          // the map cell at the grid's cell (0, 0)
  int width = 0;            // cells along x
  int height = 0;           // cells along y
  plan::Point2 origin{};    // m, the low-left corner of the map cell `lo`
};

// Why: the box cut_place() takes (below), without cutting: a caller sizes its buffers with it.
PlaceBox place_box(const PlaceGraph& graph, std::size_t place, const plan::MapGeometry& map,
                   double margin = kPlaceGridMargin);

// Why: cut_place() into `out` without allocating when `out.cells` already holds the box's
// cells (capacity): the planner's periodic path cuts into a buffer sized at start-up. `out.place`
// is left as it is (the name is the writer's to set). False, `out` unchanged, when the box holds
// more cells than the capacity.
bool cut_place_into(const PlaceGraph& graph, std::size_t place, const plan::OccupancyMap& map,
                    std::optional<plan::Point2> robot, PlaceGrid& out, double margin = kPlaceGridMargin);

// Why: cut place `place`'s bounding box, widened by `margin` (m) on every side so that the walls
// on its edges are in it (their cells lie just outside the polygon), out of `map` (on the map's
// cells: every cell the box touches); cells off the map are unknown. `robot` (m, map frame), if
// given and on the grid, is the 'P' of the text (its cell free: the robot stands there).
// Allocates (not for the periodic path).
PlaceGrid cut_place(const PlaceGraph& graph, std::size_t place, const plan::OccupancyMap& map,
                    std::optional<plan::Point2> robot = std::nullopt, double margin = kPlaceGridMargin);

// Why: the text form (docs/PLACES.md, "Place grids"): a header of `key value` lines, a line
// `grid`, then the rows north first in seed 003's characters ('.' unknown, '#' obstacle,
// ' ' free, 'P' where the robot stood: free), each exactly `width` characters.
std::string place_grid_text(const PlaceGrid& grid);

// Why: the inverse, strict: every header key once, numbers whole, the row count and every row's
// width exact, only the four characters; an error names the file and line. A 'P' is free.
plan::Result<PlaceGrid> parse_place_grid(std::string_view text, const std::string& file);

// Why: files: `<dir>/<place>.txt` (written whole to a temporary, then renamed).
std::string place_grid_path(const std::string& dir, const std::string& place);
plan::Status save_place_grid(const PlaceGrid& grid, const std::string& path);
plan::Result<PlaceGrid> load_place_grid(const std::string& path);

// Why: a loaded grid becomes knowledge of a map (on the same cells: same cell size, origins a
// whole number of cells apart, else an error and nothing changed): its obstacles occupied at the
// threshold (one miss clears one that moved) and its free cells free where the map does not know the cell; the map's own
// knowledge stays. Returns the cells written.
plan::Result<std::size_t> apply_place_grid(const PlaceGrid& grid, plan::OccupancyMap& map);

}  // namespace robuter::places
