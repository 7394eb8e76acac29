// SPDX-License-Identifier: GPL-3.0-or-later
// Drawing a PlanSnapshot's cells, path, footprints, start and goal on the plot, world frame.
#include "modules/planner/picture/plan_drawing.hpp"

#include <algorithm>

namespace robuter::plan {

namespace {

using picture::Ink;
using picture::Swatch;

const Ink kOccupied{{0.0, 0.0, 0.0}, Swatch::fill, "obstacle (map cell)"};
const Ink kAllBlocked{{0.62, 0.62, 0.62}, Swatch::fill, "grown obstacle: blocked at every heading"};
const Ink kSomeBlocked{{1.0, 0.85, 0.65}, Swatch::fill, "grown obstacle: passable at some headings"};
const Ink kUnknown{{0.92, 0.92, 0.92}, Swatch::fill, "unknown (never seen)"};
const Ink kFree{{1.0, 1.0, 1.0}, Swatch::fill, "free (seen, no obstacle)"};
const Ink kFootprint{{0.1, 0.3, 0.9}, Swatch::outline, "footprint at turns and every 0.5 m", 0.6, 1.0};
const Ink kPath{{0.85, 0.0, 0.0}, Swatch::line, "planned path", 1.0, 2.0};
const Ink kPrefix{{0.45, 0.0, 0.0}, Swatch::line, "prefix followed before the next scan", 1.0, 4.0};
const Ink kStart{{0.0, 0.6, 0.0}, Swatch::dot, "start"};
const Ink kGoal{{0.8, 0.0, 0.8}, Swatch::cross, "goal"};

// The page position of a map point.
picture::Vec2 dev(const picture::Frame& f, const MapPlacement& place, const Point2& p) {
  return f.to_device(place.world(p));
}

// Adds a map-frame polygon to the current path.
void polygon(cairo_t* cr, const picture::Frame& f, const MapPlacement& place, const Point2* c, int n) {
  for (int k = 0; k < n; ++k) {
    const picture::Vec2 d = dev(f, place, c[k]);
    if (k == 0) cairo_move_to(cr, d.x(), d.y());
    else cairo_line_to(cr, d.x(), d.y());
  }
  cairo_close_path(cr);
}

// The ink of one cell, or null for a free cell (the white background).
const Ink* cell_ink(std::uint8_t v) {
  const auto state = static_cast<CellState>(v & 3u);
  const std::uint8_t layers = v & 12u;
  if (state == CellState::Occupied) return &kOccupied;
  if (layers == PlanSnapshot::kAllBlocked) return &kAllBlocked;
  if (layers == PlanSnapshot::kSomeBlocked) return &kSomeBlocked;
  if (state == CellState::Unknown) return &kUnknown;
  return nullptr;
}

// Why one path per ink: a 300 × 300 map is one fill per colour, not 90,000.
void draw_cells(cairo_t* cr, const PlanSnapshot& s, const picture::Frame& f, const MapPlacement& place,
                picture::Legend& legend) {
  const int w = s.geometry.width, h = s.geometry.height;
  const double res = s.geometry.resolution;
  bool any_free = false;
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
  for (const Ink* ink : {&kOccupied, &kAllBlocked, &kSomeBlocked, &kUnknown}) {
    bool used = false;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const Ink* c = cell_ink(s.cells[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)]);
        if (c == nullptr) any_free = true;
        if (c != ink) continue;
        const double x0 = s.geometry.origin.x + x * res, y0 = s.geometry.origin.y + y * res;
        const Point2 corners[4] = {{x0, y0}, {x0 + res, y0}, {x0 + res, y0 + res}, {x0, y0 + res}};
        polygon(cr, f, place, corners, 4);
        used = true;
      }
    }
    if (used) {
      legend.use(cr, *ink);
      cairo_fill(cr);
    }
  }
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
  if (any_free) legend.add(kFree);
  // The map's edge: where the planner's knowledge ends.
  const double mw = w * res, mh = h * res;
  const Point2 o = s.geometry.origin;
  const Point2 edge[4] = {o, {o.x + mw, o.y}, {o.x + mw, o.y + mh}, {o.x, o.y + mh}};
  polygon(cr, f, place, edge, 4);
  cairo_set_source_rgb(cr, 0.5, 0.5, 0.5);
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
}

// The rectangle's outline at a waypoint (Rectangle plans).
void outline(cairo_t* cr, const picture::Frame& f, const MapPlacement& place, const RectangleFootprint& rect,
             const Pose2& p) {
  const double c = std::cos(p.heading), sn = std::sin(p.heading);
  const double a = 0.5 * rect.length + rect.margin, b = 0.5 * rect.width + rect.margin;
  const double cx = p.x + rect.center_offset * c, cy = p.y + rect.center_offset * sn;
  const double k[4][2] = {{a, b}, {-a, b}, {-a, -b}, {a, -b}};
  Point2 corners[4];
  for (int i = 0; i < 4; ++i) corners[i] = {cx + k[i][0] * c - k[i][1] * sn, cy + k[i][0] * sn + k[i][1] * c};
  polygon(cr, f, place, corners, 4);
  cairo_stroke(cr);
}

// The waypoints 0..n as one polyline.
void polyline(cairo_t* cr, const picture::Frame& f, const MapPlacement& place, const PlanSnapshot& s, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    const picture::Vec2 d = dev(f, place, {s.path[i].pose.x, s.path[i].pose.y});
    if (i == 0) cairo_move_to(cr, d.x(), d.y());
    else cairo_line_to(cr, d.x(), d.y());
  }
  cairo_stroke(cr);
}

}  // namespace

void draw_plan(cairo_t* cr, const PlanSnapshot& s, const picture::Frame& f, const MapPlacement& place,
               picture::Legend& legend, std::vector<picture::Label>& labels) {
  cairo_save(cr);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  picture::clip_to_plot(cr, f);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  draw_cells(cr, s, f, place, legend);
  const std::size_t n = s.path_len;
  if (s.footprint == FootprintKind::Rectangle && n > 0) {
    legend.use(cr, kFootprint, 0.6);
    cairo_set_line_width(cr, 1.0);
    const auto every = static_cast<std::size_t>(std::max(1, static_cast<int>(0.5 / s.geometry.resolution)));
    for (std::size_t i = 0; i < n; ++i) {
      const bool turn = i > 0 && s.path[i].cell.slice != s.path[i - 1].cell.slice;
      if (turn || i % every == 0 || i + 1 == n) outline(cr, f, place, s.rectangle, s.path[i].pose);
    }
  }
  if (n > 0) {
    legend.use(cr, kPath);
    cairo_set_line_width(cr, kPath.width);
    polyline(cr, f, place, s, n);
  }
  if (s.prefix_len > 1) {
    legend.use(cr, kPrefix);
    cairo_set_line_width(cr, kPrefix.width);
    polyline(cr, f, place, s, std::min(s.prefix_len, n));
  }
  const picture::Vec2 a = dev(f, place, {s.start.x, s.start.y});
  legend.use(cr, kStart);
  cairo_arc(cr, a.x(), a.y(), 5.0, 0, 2 * kPi);
  cairo_fill(cr);
  labels.push_back({a, "start", 11.0});
  const picture::Vec2 g = dev(f, place, s.goal);
  legend.use(cr, kGoal);
  cairo_set_line_width(cr, 3.0);
  cairo_move_to(cr, g.x() - 8, g.y() - 8);
  cairo_line_to(cr, g.x() + 8, g.y() + 8);
  cairo_move_to(cr, g.x() - 8, g.y() + 8);
  cairo_line_to(cr, g.x() + 8, g.y() - 8);
  cairo_stroke(cr);
  labels.push_back({g, s.goal_seq > 0 ? "XG goal" : "goal", 11.0});
  cairo_restore(cr);
}

}  // namespace robuter::plan
