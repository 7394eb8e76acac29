// SPDX-License-Identifier: GPL-3.0-or-later
// Where the world goes on the page: the plot area (metres, y up) between the title, the axes and the legend.
#pragma once

#include <cairo.h>

#include "picture/layout.hpp"

namespace robuter::picture {

// Room around the plot, px.
struct Margins {
  double left = 64.0;    // y-axis tick labels, px
  double top = 52.0;     // the title, px
  double right = 290.0;  // the legend, px
  double bottom = 76.0;  // x-axis tick labels and the scale bar, px
};

// How big a page to make.
struct FrameOptions {
  double pixels_per_metre = 0.0;  // scale, px per m; 0 = as large as makes the page min_width wide
  int min_width = 1000;           // the page is at least this wide, px
  int min_height = 440;           // … and this high (room for the legend), px
  Margins margins;                // room around the plot, px
};

// The world area shown and its place on the page; device units are px (PNG) or points (SVG, PDF).
struct Frame {
  Vec2 lo = Vec2::Zero();      // world corner with the smallest x and y, m
  Vec2 hi = Vec2::Zero();      // world corner with the largest x and y, m
  double scale = 60.0;         // px per m
  Vec2 origin = Vec2::Zero();  // page position of the plot's top-left corner (world lo.x, hi.y), px
  int width = 0;               // page width, px
  int height = 0;              // page height, px

  // Page position of a world point (m).
  Vec2 to_device(const Vec2& w) const {
    return origin + Vec2((w.x() - lo.x()) * scale, (hi.y() - w.y()) * scale);
  }
  // The plot area on the page, px.
  Rect plot() const { return {origin, to_device(Vec2(hi.x(), lo.y()))}; }
  // An empty layout of this page's size.
  Layout layout() const { return Layout{width, height, {}}; }
  // Sets the context's transform so that user units are world metres (y up); line widths set
  // afterwards are in metres too.
  void apply(cairo_t* cr) const;
};

// The page for the world box lo..hi (m): the scale asked for, or the one that fills min_width;
// the page never narrower than min_width (the legend's column takes what is left).
Frame make_frame(const Vec2& lo, const Vec2& hi, const FrameOptions& options);

}  // namespace robuter::picture
