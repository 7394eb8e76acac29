// SPDX-License-Identifier: GPL-3.0-or-later
// Whether a point lies on the planner's map, from the configuration alone (used by the link).
#pragma once

#include <cstdint>

#include "kernel/config.hpp"

namespace robuter::planner {

// Why: XG is refused for a goal off the map before anything changes; the link checks it with
// the same whole-cell geometry the planner builds: [origin, origin + cells × cell) per axis.
inline bool goal_on_map(const PlannerModuleConfig& p, std::int32_t x_tenth_mm, std::int32_t y_tenth_mm) {
  if (p.cell_mm == 0) return false;
  const std::int64_t cell = p.cell_mm;
  const std::int64_t x0 = std::int64_t{p.map_origin_x_mm} * 10, y0 = std::int64_t{p.map_origin_y_mm} * 10;
  const std::int64_t w = (p.map_width_mm / cell) * cell * 10, h = (p.map_height_mm / cell) * cell * 10;
  return x_tenth_mm >= x0 && x_tenth_mm < x0 + w && y_tenth_mm >= y0 && y_tenth_mm < y0 + h;
}

}  // namespace robuter::planner
