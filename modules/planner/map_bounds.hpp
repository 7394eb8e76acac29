// SPDX-License-Identifier: GPL-3.0-or-later
// The planner's map window: whether a goal lies on it, and where it moves for a goal off it (link and planner).
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>

#include "modules/planner/planner_params.hpp"
#include "robot/robot_model.hpp"

namespace robuter::planner {

// The planner's map in the odometry frame: [x0, x0 + w) × [y0, y0 + h), whole cells.
struct MapWindow {
  std::int64_t x0 = 0;    // lower-left corner, 0.1 mm
  std::int64_t y0 = 0;    // 0.1 mm
  std::int64_t w = 0;     // extent along x, 0.1 mm (cells × cell)
  std::int64_t h = 0;     // extent along y, 0.1 mm
  std::int64_t cell = 0;  // cell side, 0.1 mm (0: no map)
};

// A re-placement of the window by whole cells of its grid.
struct WindowShift {
  int dx = 0;  // cells along x (the new origin is the old one + dx cells)
  int dy = 0;  // cells along y
};

// Why: the window of the configured size with its lower-left corner at (x0_mm, y0_mm): the
// configured one, or where the planner moved it (PlannerStatus reports the corner).
inline MapWindow window_at(const PlannerModuleConfig& p, std::int64_t x0_mm, std::int64_t y0_mm) {
  MapWindow m;
  if (p.cell_mm == 0) return m;
  m.cell = std::int64_t{p.cell_mm} * 10;
  m.x0 = x0_mm * 10;
  m.y0 = y0_mm * 10;
  m.w = std::int64_t{p.map_width_mm / p.cell_mm} * m.cell;
  m.h = std::int64_t{p.map_height_mm / p.cell_mm} * m.cell;
  return m;
}

inline MapWindow configured_window(const PlannerModuleConfig& p) {
  return window_at(p, p.map_origin_x_mm, p.map_origin_y_mm);
}

// Why: the same whole-cell geometry the planner builds: [origin, origin + cells × cell) per axis.
inline bool on_window(const MapWindow& m, std::int64_t x_tenth_mm, std::int64_t y_tenth_mm) {
  return m.cell > 0 && x_tenth_mm >= m.x0 && x_tenth_mm < m.x0 + m.w && y_tenth_mm >= m.y0 &&
         y_tenth_mm < m.y0 + m.h;
}

// Why: XG against the configured map (kept for callers without a planner report).
inline bool goal_on_map(const PlannerModuleConfig& p, std::int32_t x_tenth_mm, std::int32_t y_tenth_mm) {
  return on_window(configured_window(p), x_tenth_mm, y_tenth_mm);
}

// Why: the room a re-placed window leaves around the robot and the goal, 0.1 mm: the body's
// reach from the axle (the farthest corner, which sweeps a disc turning in place), the planner's
// translation margin, and one cell for the snap to the grid. The Robuter: 778 + 0 + 50 = 828 mm.
inline std::int64_t window_margin(const PlannerModuleConfig& p, const robot::RobotModel& m) {
  const double reach_mm = m.body.corner_radius() * 1000.0;
  return (static_cast<std::int64_t>(std::ceil(reach_mm)) + p.margin_mm + p.cell_mm) * 10;
}

namespace detail {
// a / b rounded to the nearest integer, halves away from zero (b > 0).
inline std::int64_t div_round(std::int64_t a, std::int64_t b) {
  return a >= 0 ? (a + b / 2) / b : -((-a + b / 2) / b);
}
// Why: one axis of the placement: the shift in cells that centres [lo, hi] in the window, if
// both ends then lie at least `margin` inside it.
inline std::optional<std::int64_t> axis_shift(std::int64_t x0, std::int64_t w, std::int64_t cell,
                                              std::int64_t a, std::int64_t b, std::int64_t margin) {
  const std::int64_t lo = a < b ? a : b, hi = a < b ? b : a;
  const std::int64_t n = div_round(lo + hi - w - 2 * x0, 2 * cell);  // (centre - w/2 - x0) / cell
  const std::int64_t nx0 = x0 + n * cell;
  if (lo - nx0 < margin || nx0 + w - hi < margin) return std::nullopt;
  return n;
}
}  // namespace detail

// Why: XG's goal off the current window moves the window (docs/PLANNER.md, "The window"): centred
// between the robot and the goal, its corner snapped to whole cells of the current grid (the
// evidence of the overlap shifts by whole cells), when both then lie at least window_margin()
// inside it; otherwise none, and the goal is refused. A goal on the window needs no shift. With
// an a-priori map ([planner] map_file) the map never moves: a goal off it is refused.
inline std::optional<WindowShift> window_shift(const PlannerModuleConfig& p, const robot::RobotModel& m,
                                               const MapWindow& now, std::int64_t robot_x, std::int64_t robot_y,
                                               std::int64_t goal_x, std::int64_t goal_y) {
  if (now.cell == 0 || !p.map_file.empty()) return std::nullopt;  // a prior map's geometry is fixed
  const std::int64_t margin = window_margin(p, m);
  const auto sx = detail::axis_shift(now.x0, now.w, now.cell, robot_x, goal_x, margin);
  const auto sy = detail::axis_shift(now.y0, now.h, now.cell, robot_y, goal_y, margin);
  if (!sx || !sy) return std::nullopt;
  return WindowShift{static_cast<int>(*sx), static_cast<int>(*sy)};
}

// Why: XG's whole rule, in one place for the link and the planner: a goal on the current window
// is taken; a goal off it is taken when the window can move to hold the robot and the goal
// (never with an a-priori map file).
inline bool goal_acceptable(const PlannerModuleConfig& p, const robot::RobotModel& m, const MapWindow& now,
                            std::int64_t robot_x, std::int64_t robot_y, std::int64_t goal_x, std::int64_t goal_y) {
  return on_window(now, goal_x, goal_y) || window_shift(p, m, now, robot_x, robot_y, goal_x, goal_y).has_value();
}

}  // namespace robuter::planner
