// SPDX-License-Identifier: GPL-3.0-or-later
// The legend: one entry per colour and kind of line a picture used, gathered while it draws.
#pragma once

#include <cairo.h>

#include <string>
#include <vector>

#include "picture/frame.hpp"
#include "picture/layout.hpp"

namespace robuter::picture {

// A colour.
struct Rgb {
  double r = 0.0, g = 0.0, b = 0.0;  // red, green, blue, 0..1
};

// How an ink shows in the legend's key.
enum class Swatch { fill, outline, line, dashed, dotted, dot, cross };

// A colour with a meaning: what is drawn with it and how its key looks.
struct Ink {
  Rgb colour;                    // the colour drawn
  Swatch swatch = Swatch::fill;  // the key's shape
  std::string meaning;           // the legend's words, e.g. "obstacle"
  double alpha = 1.0;            // the key's opacity, 0..1
  double width = 2.0;            // the key's line width (line, dashed, dotted, outline), px
};

// The inks a picture used, in first-use order, one entry per meaning.
class Legend {
 public:
  // Selects `ink`'s colour at `alpha` for the next fill or stroke and records that it was used.
  void use(cairo_t* cr, const Ink& ink, double alpha = 1.0);
  // Records an ink without drawing (what a hook drew).
  void add(const Ink& ink);
  const std::vector<Ink>& entries() const { return entries_; }
  // Draws the entries in the column right of the plot, each key with its words, and records them.
  void draw(cairo_t* cr, const Frame& f, Layout& layout) const;

 private:
  std::vector<Ink> entries_;  // used inks, first use first
};

}  // namespace robuter::picture
