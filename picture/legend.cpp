// SPDX-License-Identifier: GPL-3.0-or-later
// Gathering the inks a picture used and drawing their keys in the column beside the plot.
#include "picture/legend.hpp"

#include <algorithm>

#include "picture/page.hpp"

namespace robuter::picture {

namespace {
constexpr double kKey = 30.0;  // key width, px

// The key of one ink in the box at (x, y) with height h.
void key(cairo_t* cr, const Ink& ink, double x, double y, double h) {
  cairo_set_source_rgba(cr, ink.colour.r, ink.colour.g, ink.colour.b, ink.alpha);
  cairo_set_line_width(cr, ink.width);
  const double my = y + 0.5 * h;
  switch (ink.swatch) {
    case Swatch::fill:
    case Swatch::outline:
      cairo_rectangle(cr, x + 2, y + 1, kKey - 4, h - 2);
      if (ink.swatch == Swatch::outline) {
        cairo_stroke(cr);
        break;
      }
      cairo_fill_preserve(cr);  // a thin grey rim: a white or pale fill still shows
      cairo_set_source_rgba(cr, 0.6, 0.6, 0.6, 1.0);
      cairo_set_line_width(cr, 0.5);
      cairo_stroke(cr);
      break;
    case Swatch::line:
    case Swatch::dashed:
    case Swatch::dotted: {
      const double dash[] = {ink.swatch == Swatch::dashed ? 5.0 : 2.0, 3.0};
      if (ink.swatch != Swatch::line) cairo_set_dash(cr, dash, 2, 0.0);
      cairo_move_to(cr, x, my);
      cairo_line_to(cr, x + kKey, my);
      cairo_stroke(cr);
      cairo_set_dash(cr, nullptr, 0, 0.0);
      break;
    }
    case Swatch::dot:
      cairo_arc(cr, x + 0.5 * kKey, my, 0.3 * h, 0.0, 6.2832);
      cairo_fill(cr);
      break;
    case Swatch::cross:
      cairo_move_to(cr, x + 0.5 * kKey - 5, my - 5);
      cairo_line_to(cr, x + 0.5 * kKey + 5, my + 5);
      cairo_move_to(cr, x + 0.5 * kKey - 5, my + 5);
      cairo_line_to(cr, x + 0.5 * kKey + 5, my - 5);
      cairo_stroke(cr);
      break;
  }
}
}  // namespace

void Legend::use(cairo_t* cr, const Ink& ink, double alpha) {
  add(ink);
  cairo_set_source_rgba(cr, ink.colour.r, ink.colour.g, ink.colour.b, alpha);
}

void Legend::add(const Ink& ink) {
  const auto same = [&](const Ink& e) { return e.meaning == ink.meaning; };
  if (std::none_of(entries_.begin(), entries_.end(), same)) entries_.push_back(ink);
}

// Why wrap after shrinking a little: a long meaning stays readable on two lines of 10 px
// rather than one line too small to read.
void Legend::draw(cairo_t* cr, const Frame& f, Layout& layout) const {
  const double x = f.plot().hi.x() + 24.0;
  const double tx = x + kKey + 8.0;  // where the words start, px
  const double room = f.width - 8.0 - tx;
  const auto fits = [&](const std::string& t) { return text_box(cr, t, Vec2::Zero()).hi.x() <= room; };
  double y = f.origin.y();
  for (const Ink& ink : entries_) {
    double size = 12.0;
    select_font(cr, size);
    while (size > 10.0 && !fits(ink.meaning)) select_font(cr, size -= 0.5);
    std::vector<std::string> lines{ink.meaning};
    if (!fits(ink.meaning)) {  // the longest first line that fits, the rest below
      std::size_t cut = ink.meaning.rfind(' ');
      while (cut != std::string::npos && cut > 0 && !fits(ink.meaning.substr(0, cut))) cut = ink.meaning.rfind(' ', cut - 1);
      if (cut != std::string::npos && cut > 0) lines = {ink.meaning.substr(0, cut), ink.meaning.substr(cut + 1)};
      while (!fits(lines.back()) && size > 7.0) select_font(cr, size -= 0.5);
    }
    key(cr, ink, x, y + 2.0, 14.0);
    Rect box{Vec2(x, y + 2.0), Vec2(x + kKey, y + 16.0)};
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const Vec2 base(tx, y + 13.0 + static_cast<double>(i) * (size + 3.0));
      const Rect t = text_box(cr, lines[i], base);
      box.lo = box.lo.cwiseMin(t.lo);
      box.hi = box.hi.cwiseMax(t.hi);
      cairo_set_source_rgb(cr, 0.10, 0.10, 0.10);
      cairo_move_to(cr, base.x(), base.y());
      cairo_show_text(cr, lines[i].c_str());
    }
    layout.items.push_back({Kind::legend, ink.meaning, box});
    y = box.hi.y() + 5.0;
  }
}

}  // namespace robuter::picture
