// SPDX-License-Identifier: GPL-3.0-or-later
// Title, axes, scale bar and collision-free labels, each recorded in the Layout it returns through.
#include "picture/page.hpp"

#include <fontconfig/fontconfig.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <ctime>

namespace robuter::picture {

namespace {
constexpr double kGap = 2.0;  // px kept between a text and its neighbours

// Dark grey for words, ticks and frames.
void ink_text(cairo_t* cr) { cairo_set_source_rgb(cr, 0.10, 0.10, 0.10); }

// Draws `text` at `at` (baseline start) and records it; its box, px.
Rect show(cairo_t* cr, Layout& layout, Kind kind, const std::string& text, const Vec2& at) {
  const Rect box = text_box(cr, text, at);
  ink_text(cr);
  cairo_move_to(cr, at.x(), at.y());
  cairo_show_text(cr, text.c_str());
  layout.items.push_back({kind, text, box});
  return box;
}

// A box grown by the gap on every side (what must be free around a text).
Rect padded(const Rect& r) { return {r.lo - Vec2::Constant(kGap), r.hi + Vec2::Constant(kGap)}; }

// A round step (1, 2 or 5 × 10^k m) at least `min_m` long.
double round_step(double min_m) {
  const double p = std::pow(10.0, std::floor(std::log10(min_m)));
  for (const double k : {1.0, 2.0, 5.0, 10.0})
    if (k * p >= min_m - 1e-12) return k * p;
  return 10.0 * p;
}

// A tick value as text: no trailing zeros, no "-0".
std::string number(double v) {
  char t[32];
  std::snprintf(t, sizeof t, "%g", std::abs(v) < 1e-9 ? 0.0 : v);
  return t;
}
}  // namespace

void select_font(cairo_t* cr, double size_px, bool bold) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size_px);
}

// Why font extents (ascent, descent) rather than ink extents: every text of one size gets the
// same height, and a label "1" is as tall as "8".
Rect text_box(cairo_t* cr, const std::string& text, const Vec2& at) {
  cairo_font_extents_t fe;
  cairo_text_extents_t te;
  cairo_font_extents(cr, &fe);
  cairo_text_extents(cr, text.c_str(), &te);
  return {Vec2(at.x() + std::min(0.0, te.x_bearing), at.y() - fe.ascent),
          Vec2(at.x() + std::max(te.x_advance, te.x_bearing + te.width), at.y() + fe.descent)};
}

void draw_title(cairo_t* cr, const Frame& f, const std::string& title, Layout& layout) {
  const double room = f.width - 20.0;
  double size = 17.0;
  select_font(cr, size, true);
  while (size > 8.0 && text_box(cr, title, Vec2::Zero()).hi.x() > room) select_font(cr, size -= 0.5, true);
  std::string shown = title;
  while (shown.size() > 4 && text_box(cr, shown, Vec2::Zero()).hi.x() > room) shown = shown.substr(0, shown.size() - 4) + "...";
  show(cr, layout, Kind::title, shown, Vec2(10.0, 0.5 * f.origin.y()));
}

void draw_axes(cairo_t* cr, const Frame& f, Layout& layout) {
  const Rect plot = f.plot();
  ink_text(cr);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, plot.lo.x(), plot.lo.y(), plot.hi.x() - plot.lo.x(), plot.hi.y() - plot.lo.y());
  cairo_stroke(cr);
  select_font(cr, 11.0);
  // The axis names first: a tick label that would cover one is the one left out.
  const Rect xn = text_box(cr, "x (m)", Vec2::Zero());
  show(cr, layout, Kind::axis, "x (m)", Vec2(plot.hi.x() - xn.hi.x(), plot.hi.y() + 30.0));
  show(cr, layout, Kind::axis, "y (m)", Vec2(std::max(2.0, plot.lo.x() - 40.0), plot.lo.y() - 5.0));
  const double step = round_step(70.0 / f.scale);
  for (int axis = 0; axis < 2; ++axis) {
    for (double v = std::ceil(f.lo[axis] / step - 1e-9) * step; v <= f.hi[axis] + 1e-9; v += step) {
      const Vec2 at = f.to_device(axis == 0 ? Vec2(v, f.lo.y()) : Vec2(f.lo.x(), v));
      const Vec2 dir = axis == 0 ? Vec2(0.0, 1.0) : Vec2(-1.0, 0.0);
      ink_text(cr);
      cairo_move_to(cr, at.x(), at.y());
      cairo_line_to(cr, at.x() + 5.0 * dir.x(), at.y() + 5.0 * dir.y());
      cairo_stroke(cr);
      const std::string t = number(v);
      const Rect b = text_box(cr, t, Vec2::Zero());
      const Vec2 base = axis == 0 ? Vec2(at.x() - 0.5 * b.hi.x(), at.y() + 18.0) : Vec2(at.x() - 8.0 - b.hi.x(), at.y() + 4.0);
      if (layout.free(padded(text_box(cr, t, base)))) show(cr, layout, Kind::axis, t, base);
    }
  }
}

void draw_scale_bar(cairo_t* cr, const Frame& f, Layout& layout) {
  const double metres = round_step(90.0 / f.scale);
  const double len = metres * f.scale;
  const Rect plot = f.plot();
  const Vec2 a(plot.lo.x(), plot.hi.y() + 52.0);  // left end of the bar, px
  // Two halves, dark and light, framed: readable on any background.
  for (int half = 0; half < 2; ++half) {
    cairo_rectangle(cr, a.x() + half * 0.5 * len, a.y() - 3.0, 0.5 * len, 6.0);
    if (half == 0) ink_text(cr);
    else cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_fill_preserve(cr);
    ink_text(cr);
    cairo_set_line_width(cr, 1.0);
    cairo_stroke(cr);
  }
  select_font(cr, 11.0);
  const std::string t = number(metres) + " m";
  const Rect text = text_box(cr, t, Vec2(a.x() + len + 6.0, a.y() + 4.0));
  ink_text(cr);
  cairo_move_to(cr, a.x() + len + 6.0, a.y() + 4.0);
  cairo_show_text(cr, t.c_str());
  layout.items.push_back({Kind::scale_bar, t, {Vec2(a.x(), std::min(a.y() - 4.0, text.lo.y())), text.hi}});
}

bool place_label(cairo_t* cr, const Frame& f, Layout& layout, const Vec2& anchor, const std::string& text,
                 double size_px) {
  select_font(cr, size_px);
  const Rect b = text_box(cr, text, Vec2::Zero());
  const Vec2 size = b.hi - b.lo;
  // Box corners relative to the anchor: right-up, right-down, left-up, left-down, above, below;
  // then the same twice and three times as far.
  static constexpr std::array<std::array<double, 2>, 6> kSides{
      {{1, -1}, {1, 1}, {-1, -1}, {-1, 1}, {0, -1}, {0, 1}}};
  for (const double reach : {3.0, 9.0, 16.0}) {
    for (const auto& s : kSides) {
      const Vec2 centre = anchor + Vec2(s[0] * (reach + 0.5 * size.x()), s[1] * (reach + 0.5 * size.y()));
      const Vec2 base = centre - 0.5 * size - b.lo;
      const Rect box = text_box(cr, text, base);
      if (!box.inside(f.plot()) || !layout.free(padded(box))) continue;
      show(cr, layout, Kind::label, text, base);
      return true;
    }
  }
  return false;
}

void clip_to_plot(cairo_t* cr, const Frame& f) {
  const Rect plot = f.plot();
  cairo_rectangle(cr, plot.lo.x(), plot.lo.y(), plot.hi.x() - plot.lo.x(), plot.hi.y() - plot.lo.y());
  cairo_clip(cr);
}

void draw_words(cairo_t* cr, const Frame& f, const std::string& title, const Legend& legend,
                const std::vector<Label>& labels, Layout& layout) {
  draw_title(cr, f, title, layout);
  draw_axes(cr, f, layout);
  draw_scale_bar(cr, f, layout);
  legend.draw(cr, f, layout);
  for (const Label& l : labels) place_label(cr, f, layout, l.anchor, l.text, l.size);
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm t{};
  gmtime_r(&now, &t);
  char s[32];
  std::strftime(s, sizeof s, "%Y-%m-%d %H:%M UTC", &t);
  return s;
}

// Cairo first (it holds fontconfig objects), then fontconfig itself.
void release_caches() {
  cairo_debug_reset_static_data();
  FcFini();
}

}  // namespace robuter::picture
