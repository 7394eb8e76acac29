// SPDX-License-Identifier: GPL-3.0-or-later
// Cairo overlay of the place graph; colours shared with its legend keys.
#include "modules/places/place_picture.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace robuter::places {

namespace {

const picture::Ink kArea{{0.20, 0.50, 0.85}, picture::Swatch::outline, "place (area)", 0.9, 1.0};
const picture::Ink kLink{{0.20, 0.50, 0.85}, picture::Swatch::dashed, "door: centre - door - centre", 0.9, 1.2};
const picture::Ink kDoor{{0.85, 0.35, 0.10}, picture::Swatch::dot, "door (place graph)", 1.0, 2.0};
const picture::Ink kCentre{{0.10, 0.25, 0.60}, picture::Swatch::dot, "place centre, name", 1.0, 2.0};
const picture::Ink kGridObstacle{{0.55, 0.10, 0.10}, picture::Swatch::fill, "place grid: obstacle ('#')", 0.85, 1.0};
const picture::Ink kGridFree{{0.30, 0.70, 0.35}, picture::Swatch::fill, "place grid: free (' ')", 0.30, 1.0};
const picture::Ink kGridRobot{{0.10, 0.10, 0.10}, picture::Swatch::outline, "place grid: scanned from ('P')", 1.0, 1.5};
const picture::Ink kRoute{{0.10, 0.65, 0.20}, picture::Swatch::line, "route over places", 1.0, 4.0};

void move(cairo_t* cr, const sim::View& view, const Vec2& w) {
  const Vec2 d = view.to_device(w);
  cairo_move_to(cr, d.x(), d.y());
}
void line(cairo_t* cr, const sim::View& view, const Vec2& w) {
  const Vec2 d = view.to_device(w);
  cairo_line_to(cr, d.x(), d.y());
}
void dot(cairo_t* cr, const sim::View& view, const Vec2& w, double radius) {
  const Vec2 d = view.to_device(w);
  cairo_new_sub_path(cr);
  cairo_arc(cr, d.x(), d.y(), radius, 0.0, 2.0 * std::numbers::pi);
  cairo_fill(cr);
}
void colour(cairo_t* cr, const picture::Ink& ink, double alpha) {
  cairo_set_source_rgba(cr, ink.colour.r, ink.colour.g, ink.colour.b, alpha);
}

}  // namespace

sim::DrawHook place_graph_overlay(const PlaceGraph& graph, const PlaceRoute* route) {
  return [&graph, route](cairo_t* cr, const sim::View& view) {
    cairo_save(cr);
    for (const Place& p : graph.places()) {
      move(cr, view, p.area.front());
      for (const Vec2& v : p.area) line(cr, view, v);
      cairo_close_path(cr);
      colour(cr, kArea, 0.08);
      cairo_fill_preserve(cr);
      colour(cr, kArea, kArea.alpha);
      cairo_set_line_width(cr, kArea.width);
      cairo_stroke(cr);
    }
    const double dashes[] = {4.0, 3.0};
    cairo_set_dash(cr, dashes, 2, 0.0);
    cairo_set_line_width(cr, kLink.width);
    colour(cr, kLink, kLink.alpha);
    for (const Door& d : graph.doors()) {
      move(cr, view, graph.places()[d.a].centre);
      line(cr, view, d.at);
      line(cr, view, graph.places()[d.b].centre);
      cairo_stroke(cr);
    }
    cairo_set_dash(cr, nullptr, 0, 0.0);
    if (route != nullptr && route->found && !route->legs.empty()) {
      colour(cr, kRoute, 0.85);
      cairo_set_line_width(cr, kRoute.width);
      cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
      move(cr, view, graph.places()[route->from].centre);
      for (const RouteLeg& leg : route->legs) {
        line(cr, view, graph.doors()[leg.door].at);
        line(cr, view, graph.places()[leg.place].centre);
      }
      cairo_stroke(cr);
    }
    colour(cr, kDoor, 1.0);
    for (const Door& d : graph.doors()) dot(cr, view, d.at, 3.0);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 10.0);
    for (const Place& p : graph.places()) {
      colour(cr, kCentre, 1.0);
      dot(cr, view, p.centre, 3.5);
      const Vec2 d = view.to_device(p.centre);
      cairo_text_extents_t ext;
      cairo_text_extents(cr, p.name.c_str(), &ext);
      cairo_move_to(cr, d.x() - ext.width / 2.0 - ext.x_bearing, d.y() + 14.0);
      cairo_show_text(cr, p.name.c_str());
    }
    cairo_restore(cr);
  };
}

sim::DrawHook place_grids_overlay(const std::vector<PlaceGrid>& grids, sim::DrawHook then) {
  return [&grids, then = std::move(then)](cairo_t* cr, const sim::View& view) {
    cairo_save(cr);
    for (const PlaceGrid& g : grids) {
      for (const auto& [ink, state] : {std::pair{&kGridFree, plan::CellState::Free},
                                       std::pair{&kGridObstacle, plan::CellState::Occupied}}) {
        colour(cr, *ink, ink->alpha);
        for (int y = 0; y < g.height; ++y)
          for (int x = 0; x < g.width; ++x) {
            if (g.at(x, y) != state) continue;
            const Vec2 a = view.to_device(Vec2(g.origin.x + x * g.cell, g.origin.y + y * g.cell));
            const Vec2 b = view.to_device(Vec2(g.origin.x + (x + 1) * g.cell, g.origin.y + (y + 1) * g.cell));
            cairo_rectangle(cr, std::min(a.x(), b.x()), std::min(a.y(), b.y()), std::abs(b.x() - a.x()),
                            std::abs(b.y() - a.y()));
          }
        cairo_fill(cr);
      }
      if (g.scanned_from) {
        const Vec2 d = view.to_device(Vec2(g.origin.x + (g.scanned_from->x + 0.5) * g.cell,
                                           g.origin.y + (g.scanned_from->y + 0.5) * g.cell));
        colour(cr, kGridRobot, 1.0);
        cairo_set_line_width(cr, kGridRobot.width);
        cairo_new_sub_path(cr);
        cairo_arc(cr, d.x(), d.y(), 5.0, 0.0, 2.0 * std::numbers::pi);
        cairo_stroke(cr);
      }
    }
    cairo_restore(cr);
    if (then) then(cr, view);
  };
}

std::vector<picture::Ink> place_grid_keys() { return {kGridObstacle, kGridFree, kGridRobot}; }

std::vector<picture::Ink> place_graph_keys(bool with_route) {
  std::vector<picture::Ink> keys = {kArea, kLink, kDoor, kCentre};
  if (with_route) keys.push_back(kRoute);
  return keys;
}

}  // namespace robuter::places
