// SPDX-License-Identifier: GPL-3.0-or-later
// The words around and on a plot: title, axis ticks in metres, scale bar, and labels nudged clear of each other.
#pragma once

#include <cairo.h>

#include <string>
#include <vector>

#include "picture/frame.hpp"
#include "picture/layout.hpp"
#include "picture/legend.hpp"

namespace robuter::picture {

// Why one face: DejaVu Sans (Debian's fonts-dejavu-core), through cairo's toy text API; only
// ever called outside the kernel's thread (pictures are drawn after a run or by a writer thread).
void select_font(cairo_t* cr, double size_px, bool bold = false);

// The box text would take with its baseline starting at `at` in the current font, px.
Rect text_box(cairo_t* cr, const std::string& text, const Vec2& at);

// The title (what, when, outcome) across the top, shrunk to fit the page's width.
void draw_title(cairo_t* cr, const Frame& f, const std::string& title, Layout& layout);

// The plot's border, ticks every 1, 2 or 5 × 10^k m along the bottom and left edges with their
// values, and the axis names "x (m)", "y (m)"; a tick label that would collide is left out.
void draw_axes(cairo_t* cr, const Frame& f, Layout& layout);

// A bar of a round length in metres under the plot, labelled with it.
void draw_scale_bar(cairo_t* cr, const Frame& f, Layout& layout);

// Small text near `anchor` (px), on the plot: tried on each side of it, then further out; drawn
// at the first place that overlaps nothing laid out, else dropped (false).
bool place_label(cairo_t* cr, const Frame& f, Layout& layout, const Vec2& anchor, const std::string& text,
                 double size_px = 11.0);

// A label to place once the plot is drawn: its anchor on the page and its words.
struct Label {
  Vec2 anchor;         // the point it names, px
  std::string text;    // the words
  double size = 11.0;  // font size, px
};

// Clips the context to the plot area (layers drawn after stay off the margins).
void clip_to_plot(cairo_t* cr, const Frame& f);

// Everything around the plot, then on it: the title, the axes, the scale bar, the legend's
// column, and the labels in order (each where it collides with nothing, else dropped).
void draw_words(cairo_t* cr, const Frame& f, const std::string& title, const Legend& legend,
                const std::vector<Label>& labels, Layout& layout);

// A UTC date and time for titles, "2026-12-02 00:45 UTC".
std::string utc_now();

// Frees cairo's and fontconfig's process-wide caches (drawing text fills them). Call once a
// program or a test run checked by LeakSanitizer has drawn its last picture; nothing may be
// drawn meanwhile (a later picture fills them again).
void release_caches();

}  // namespace robuter::picture
