// Drawing a PlanSnapshot into a PNG with cairo.
#include "modules/planner/picture/plan_picture.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>

namespace robuter::plan {

namespace {
// Why: the rectangle's outline at a waypoint (Rectangle plans).
void outline(cairo_t* cr, const RectangleFootprint& rect, const Pose2& p, auto px, auto py) {
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
}  // namespace

Status write_plan_picture(const PlanSnapshot& snap, const std::string& path) {
  const int w = snap.geometry.width, h = snap.geometry.height;
  if (w <= 0 || h <= 0 || snap.cells.size() != static_cast<std::size_t>(w) * static_cast<std::size_t>(h))
    return Error{path, 0, "empty snapshot: nothing to draw"};
  const int scale = std::clamp(1200 / std::max(w, h), 1, 8);
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w * scale, h * scale);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::uint8_t v = snap.cells[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)];
      const auto state = static_cast<CellState>(v & 3u);
      const std::uint8_t layers = v & 12u;
      double r = 1.0, g = 1.0, b = 1.0;
      if (state == CellState::Occupied) r = g = b = 0.0;
      else if (layers == PlanSnapshot::kAllBlocked) r = g = b = 0.62;
      else if (layers == PlanSnapshot::kSomeBlocked) r = 1.0, g = 0.85, b = 0.65;
      else if (state == CellState::Unknown) r = g = b = 0.92;
      else continue;  // free: the white background
      cairo_set_source_rgb(cr, r, g, b);
      cairo_rectangle(cr, x * scale, (h - 1 - y) * scale, scale, scale);
      cairo_fill(cr);
    }
  }
  const double res = snap.geometry.resolution;
  const Point2 o = snap.geometry.origin;
  auto px = [&](double wx) { return (wx - o.x) / res * scale; };
  auto py = [&](double wy) { return (h - (wy - o.y) / res) * scale; };
  const std::size_t n = snap.path_len;
  if (snap.footprint == FootprintKind::Rectangle && n > 0) {
    cairo_set_source_rgba(cr, 0.1, 0.3, 0.9, 0.6);
    cairo_set_line_width(cr, 1.0);
    const auto every = static_cast<std::size_t>(std::max(1, static_cast<int>(0.5 / res)));
    for (std::size_t i = 0; i < n; ++i) {
      const bool turn = i > 0 && snap.path[i].cell.slice != snap.path[i - 1].cell.slice;
      if (turn || i % every == 0 || i + 1 == n) outline(cr, snap.rectangle, snap.path[i].pose, px, py);
    }
  }
  if (n > 0) {
    cairo_set_source_rgb(cr, 0.85, 0.0, 0.0);
    cairo_set_line_width(cr, std::max(1.5, scale * 0.6));
    cairo_move_to(cr, px(snap.path[0].pose.x), py(snap.path[0].pose.y));
    for (std::size_t i = 0; i < n; ++i) cairo_line_to(cr, px(snap.path[i].pose.x), py(snap.path[i].pose.y));
    cairo_stroke(cr);
  }
  if (snap.prefix_len > 1) {
    cairo_set_source_rgb(cr, 0.45, 0.0, 0.0);
    cairo_set_line_width(cr, std::max(3.0, scale * 1.2));
    cairo_move_to(cr, px(snap.path[0].pose.x), py(snap.path[0].pose.y));
    for (std::size_t i = 0; i < std::min(snap.prefix_len, n); ++i)
      cairo_line_to(cr, px(snap.path[i].pose.x), py(snap.path[i].pose.y));
    cairo_stroke(cr);
  }
  const double mark = std::max(3.0, 2.0 * scale);
  cairo_set_source_rgb(cr, 0.0, 0.6, 0.0);
  cairo_arc(cr, px(snap.start.x), py(snap.start.y), mark, 0, 2 * kPi);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0.8, 0.0, 0.8);
  cairo_arc(cr, px(snap.goal.x), py(snap.goal.y), mark, 0, 2 * kPi);
  cairo_fill(cr);
  cairo_destroy(cr);
  const cairo_status_t st = cairo_surface_write_to_png(surface, path.c_str());
  cairo_surface_destroy(surface);
  if (st != CAIRO_STATUS_SUCCESS) return Error{path, 0, std::string("cannot write PNG: ") + cairo_status_to_string(st)};
  return Ok{};
}

}  // namespace robuter::plan
