// Drawing a planner's map, C-space and path into a PNG with cairo.
#include "tools/robuter-plan/picture.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>

namespace robuter::plan::tool {

Status write_picture(const Planner& planner, const Pose2& start, Point2 goal,
                     const std::string& path) {
  const OccupancyMap& map = planner.map();
  const int w = map.width(), h = map.height();
  const int scale = std::clamp(1200 / std::max(w, h), 1, 8);
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w * scale, h * scale);
  cairo_t* cr = cairo_create(surface);
  const int slices = planner.slices();
  // Cells: free white, unknown light grey, expanded obstacle (all slices) mid grey, expanded
  // in some slices only (the rectangle fits at some headings) pale orange, obstacle black.
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const Cell c{x, y};
      int blocked = 0;
      for (int k = 0; k < slices; ++k) blocked += planner.expanded(k).at(c) == kBlocked ? 1 : 0;
      double r = 1.0, g = 1.0, b = 1.0;
      const CellState s = map.state(c);
      if (s == CellState::Occupied) r = g = b = 0.0;
      else if (blocked == slices) r = g = b = 0.62;
      else if (blocked > 0) r = 1.0, g = 0.85, b = 0.65;
      else if (s == CellState::Unknown) r = g = b = 0.92;
      cairo_set_source_rgb(cr, r, g, b);
      cairo_rectangle(cr, x * scale, (h - 1 - y) * scale, scale, scale);
      cairo_fill(cr);
    }
  }
  const double res = map.resolution();
  const Point2 o = map.geometry().origin;
  auto px = [&](double wx) { return (wx - o.x) / res * scale; };
  auto py = [&](double wy) { return (h - (wy - o.y) / res) * scale; };
  const auto& wps = planner.waypoints();
  // Footprints along a rectangle plan: at every turn and every ~0.5 m.
  if (planner.config().footprint == FootprintKind::Rectangle && !wps.empty()) {
    const RectangleFootprint& rect = planner.config().rectangle;
    cairo_set_source_rgba(cr, 0.1, 0.3, 0.9, 0.6);
    cairo_set_line_width(cr, 1.0);
    const int every = std::max(1, static_cast<int>(0.5 / res));
    for (std::size_t i = 0; i < wps.size(); ++i) {
      const bool turn = i > 0 && wps[i].cell.slice != wps[i - 1].cell.slice;
      if (!(turn || i % static_cast<std::size_t>(every) == 0 || i + 1 == wps.size())) continue;
      const Pose2 p = wps[i].pose;
      const double c = std::cos(p.heading), s = std::sin(p.heading);
      const double a = 0.5 * rect.length + rect.margin, b = 0.5 * rect.width + rect.margin;
      const double cx = p.x + rect.center_offset * c, cy = p.y + rect.center_offset * s;
      const double corners[4][2] = {{a, b}, {-a, b}, {-a, -b}, {a, -b}};
      for (int k = 0; k < 4; ++k) {
        const double wx = cx + corners[k][0] * c - corners[k][1] * s;
        const double wy = cy + corners[k][0] * s + corners[k][1] * c;
        if (k == 0) cairo_move_to(cr, px(wx), py(wy));
        else cairo_line_to(cr, px(wx), py(wy));
      }
      cairo_close_path(cr);
      cairo_stroke(cr);
    }
  }
  if (!wps.empty()) {
    cairo_set_source_rgb(cr, 0.85, 0.0, 0.0);
    cairo_set_line_width(cr, std::max(1.5, scale * 0.6));
    cairo_move_to(cr, px(wps[0].pose.x), py(wps[0].pose.y));
    for (const Waypoint& wp : wps) cairo_line_to(cr, px(wp.pose.x), py(wp.pose.y));
    cairo_stroke(cr);
  }
  const double mark = std::max(3.0, 2.0 * scale);
  cairo_set_source_rgb(cr, 0.0, 0.6, 0.0);
  cairo_arc(cr, px(start.x), py(start.y), mark, 0, 2 * kPi);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0.8, 0.0, 0.8);
  cairo_arc(cr, px(goal.x), py(goal.y), mark, 0, 2 * kPi);
  cairo_fill(cr);
  cairo_destroy(cr);
  const cairo_status_t st = cairo_surface_write_to_png(surface, path.c_str());
  cairo_surface_destroy(surface);
  if (st != CAIRO_STATUS_SUCCESS) return Error{path, 0, std::string("cannot write PNG: ") + cairo_status_to_string(st)};
  return Ok{};
}

}  // namespace robuter::plan::tool
