// SPDX-License-Identifier: GPL-3.0-or-later
// Builds the uniform edge grid in two passes (count, then fill) into compressed rows.
#include "hal/sim/segment_grid.hpp"

#include <limits>

namespace robuter::sim {

// Bounds of all edges, padded by one cell, then every edge goes to the cells its box covers.
void SegmentGrid::build(const std::vector<Segment>& segments, double cell) {
  cell_ = cell > 0.0 ? cell : 0.5;
  start_.clear();
  items_.clear();
  if (segments.empty()) {
    nx_ = ny_ = 0;
    return;
  }
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity());
  Vec2 hi = -lo;
  for (const auto& s : segments) {
    lo = lo.cwiseMin(s.a).cwiseMin(s.b);
    hi = hi.cwiseMax(s.a).cwiseMax(s.b);
  }
  origin_ = lo - Vec2::Constant(cell_);
  nx_ = static_cast<int>(std::ceil((hi.x() - origin_.x()) / cell_)) + 1;
  ny_ = static_cast<int>(std::ceil((hi.y() - origin_.y()) / cell_)) + 1;
  far_ = origin_ + Vec2(nx_ * cell_, ny_ * cell_);
  const std::size_t cells = static_cast<std::size_t>(nx_) * ny_;
  start_.assign(cells + 1, 0);
  auto each_cell = [&](const Segment& s, auto&& visit) {
    const Vec2 a = s.a.cwiseMin(s.b), b = s.a.cwiseMax(s.b);
    for (int cy = clamp_y(a.y()); cy <= clamp_y(b.y()); ++cy)
      for (int cx = clamp_x(a.x()); cx <= clamp_x(b.x()); ++cx)
        visit(static_cast<std::size_t>(cy) * nx_ + cx);
  };
  for (const auto& s : segments) each_cell(s, [&](std::size_t c) { ++start_[c + 1]; });
  for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
  items_.resize(start_[cells]);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::uint32_t i = 0; i < segments.size(); ++i)
    each_cell(segments[i], [&](std::size_t c) { items_[fill[c]++] = i; });
}

}  // namespace robuter::sim
