// SPDX-License-Identifier: GPL-3.0-or-later
// Sizing the page around the world box and the world-to-page transform.
#include "picture/frame.hpp"

#include <algorithm>
#include <cmath>

namespace robuter::picture {

void Frame::apply(cairo_t* cr) const {
  cairo_translate(cr, origin.x(), origin.y());
  cairo_scale(cr, scale, -scale);
  cairo_translate(cr, -lo.x(), -hi.y());
}

Frame make_frame(const Vec2& lo, const Vec2& hi, const FrameOptions& o) {
  Frame f;
  f.lo = lo.cwiseMin(hi);
  f.hi = hi.cwiseMax(lo);
  const Vec2 size = (f.hi - f.lo).cwiseMax(Vec2::Constant(0.1));
  f.hi = f.lo + size;
  const Margins& m = o.margins;
  const double fit = (o.min_width - m.left - m.right) / size.x();
  f.scale = o.pixels_per_metre > 0.0 ? o.pixels_per_metre : std::clamp(fit, 10.0, 400.0);
  f.origin = Vec2(m.left, m.top);
  const double plot_w = std::ceil(size.x() * f.scale - 1e-6), plot_h = std::ceil(size.y() * f.scale - 1e-6);
  f.width = std::max(o.min_width, static_cast<int>(m.left + plot_w + m.right));
  f.height = std::max(o.min_height, static_cast<int>(m.top + plot_h + m.bottom));
  return f;
}

}  // namespace robuter::picture
