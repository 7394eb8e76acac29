// SPDX-License-Identifier: GPL-3.0-or-later
// Reading, checking and converting the [planner] map_file.
#include "modules/planner/prior_map.hpp"

#include <fmt/format.h>

#include <cmath>

#include "modules/planner/lib/map_file.hpp"
#include "kernel/input_file.hpp"

namespace robuter::planner {

namespace {
constexpr std::size_t kMaxMapFileBytes = 8 * 1024 * 1024;  // largest map file read, bytes

// Why: the configuration counts in whole mm; a file value that is not one cannot agree with it.
bool whole_mm(double m, long long& out) {
  const double mm = m * 1000.0;
  if (!std::isfinite(mm) || std::abs(mm) > 1e9 || std::abs(mm - std::round(mm)) > 1e-3) return false;
  out = std::llround(mm);
  return true;
}
}  // namespace

plan::Result<PriorMap> load_prior_map(PlannerModuleConfig& p, const std::string& config_file) {
  const std::string& name = p.map_file;
  // A folder, a device or a huge file is refused, not read (kernel/input_file.hpp); 8 MB holds
  // any map the planner accepts (a disc map of 1 M cells is about 2 MB).
  std::string text;
  if (auto why = read_input_file(name, text, kMaxMapFileBytes)) return plan::Error{name, 0, *why};
  auto header = plan::parse_map_header(text, name);
  if (!header) return header.error();
  const plan::MapHeader& h = *header;
  const plan::MapGeometry& g = h.geometry;
  const auto where = [&](int line) { return fmt::format("{}:{}", config_file, line); };

  long long cell = 0, ox = 0, oy = 0;
  if (!whole_mm(g.resolution, cell) || cell < 10 || cell > 500)
    return plan::Error{name, h.resolution_line,
                       fmt::format("resolution {} m is not a whole number of mm from 10 to 500", g.resolution)};
  if (!whole_mm(g.origin.x, ox) || !whole_mm(g.origin.y, oy) || std::llabs(ox) > 1'000'000 || std::llabs(oy) > 1'000'000)
    return plan::Error{name, h.origin_line, "origin must be whole mm within 1 km of the odometry frame's origin"};
  const long long width_mm = g.width * cell, height_mm = g.height * cell;
  const auto& L = p.geometry_lines;  // origin x, origin y, width, height, cell
  if (L[4] && p.cell_mm != cell)
    return plan::Error{name, h.resolution_line,
                       fmt::format("resolution {} mm disagrees with planner.cell_mm = {} ({}); remove the key or make it agree",
                                   cell, p.cell_mm, where(L[4]))};
  if (L[0] && p.map_origin_x_mm != ox)
    return plan::Error{name, h.origin_line, fmt::format("origin x {} mm disagrees with planner.map_origin_x_mm = {} ({})",
                                                        ox, p.map_origin_x_mm, where(L[0]))};
  if (L[1] && p.map_origin_y_mm != oy)
    return plan::Error{name, h.origin_line, fmt::format("origin y {} mm disagrees with planner.map_origin_y_mm = {} ({})",
                                                        oy, p.map_origin_y_mm, where(L[1]))};
  if (L[2] && p.map_width_mm / cell != g.width)
    return plan::Error{name, h.width_line, fmt::format("width {} cells ({} mm) disagrees with planner.map_width_mm = {} ({})",
                                                       g.width, width_mm, p.map_width_mm, where(L[2]))};
  if (L[3] && p.map_height_mm / cell != g.height)
    return plan::Error{name, h.height_line, fmt::format("height {} cells ({} mm) disagrees with planner.map_height_mm = {} ({})",
                                                        g.height, height_mm, p.map_height_mm, where(L[3]))};
  const long long cells = static_cast<long long>(g.width) * g.height;
  if (const long long limit = planner_cell_limit(p); cells > limit)
    return plan::Error{name, h.width_line, fmt::format("a map of {} cells is too large for the {} planner (at most {})",
                                                       cells, p.footprint, limit)};

  auto file = plan::parse_map(text, name);
  if (!file) return file.error();
  // The counts are evidence in hits, kept as they are; the firmware's threshold judges them.
  // A cell the file calls free must not become an obstacle (nor the reverse).
  const auto threshold = static_cast<std::uint8_t>(p.hit_threshold);
  plan::OccupancyMap map(g, threshold, static_cast<std::uint8_t>(p.initial_count));
  int obstacles = 0;
  for (int y = 0; y < g.height; ++y) {
    for (int x = 0; x < g.width; ++x) {
      const std::uint8_t n = file->count({x, y});
      if (n == plan::OccupancyMap::kUnknown) continue;
      const bool was = file->state({x, y}) == plan::CellState::Occupied, is = n >= threshold;
      if (was != is)
        return plan::Error{name, h.data_line + g.height - y,
                           fmt::format("cell ({}, {}) has count {}: {} with the file's threshold {} but {} with "
                                       "planner.hit_threshold = {}", x, y, n, was ? "an obstacle" : "free", h.threshold,
                                       is ? "an obstacle" : "free", p.hit_threshold)};
      map.set_count({x, y}, n);
      obstacles += is ? 1 : 0;
    }
  }
  map.clear_changes();
  p.cell_mm = static_cast<std::uint32_t>(cell);
  p.map_origin_x_mm = static_cast<std::int32_t>(ox);
  p.map_origin_y_mm = static_cast<std::int32_t>(oy);
  p.map_width_mm = static_cast<std::uint32_t>(width_mm);
  p.map_height_mm = static_cast<std::uint32_t>(height_mm);
  std::string note = fmt::format("planner.map_file {}: {} x {} cells of {} mm from ({}, {}) mm, {} obstacle cells "
                                 "(the file's geometry)", name, g.width, g.height, cell, ox, oy, obstacles);
  return PriorMap{std::move(map), std::move(note)};
}

}  // namespace robuter::planner
