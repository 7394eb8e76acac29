// SPDX-License-Identifier: GPL-3.0-or-later
// A coarse uniform grid over the world's obstacle edges, so queries touch only nearby edges.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "hal/sim/geometry.hpp"

namespace robuter::sim {

// Per-caller scratch for grid queries: remembers which edges a query already visited so each
// edge is reported once. Sized once (prepare), so queries never allocate.
struct GridScratch {
  std::vector<std::uint32_t> stamp;  // last query epoch that visited each edge
  std::uint32_t epoch = 0;           // current query's epoch

  // Sizes the stamp table for `segments` edges; call at construction, not per query.
  void prepare(std::size_t segments) {
    stamp.assign(segments, 0);
    epoch = 0;
  }

  // Starts a new query; on the (rare) wrap-around, clears the stamps.
  std::uint32_t next_epoch() {
    if (++epoch == 0) {
      std::fill(stamp.begin(), stamp.end(), 0u);
      epoch = 1;
    }
    return epoch;
  }
};

// Edges bucketed by the cells their bounding boxes cover (compressed rows: no per-cell vectors).
class SegmentGrid {
 public:
  // Buckets `segments` into square cells of side `cell` metres covering their bounds.
  void build(const std::vector<Segment>& segments, double cell);

  // Calls f(index) once for each edge bucketed in a cell that meets the box [lo, hi].
  template <class F>
  void for_each_near(const Vec2& lo, const Vec2& hi, GridScratch& scratch, F&& f) const {
    if (nx_ == 0 || misses(lo, hi)) return;
    const int x0 = clamp_x(lo.x()), x1 = clamp_x(hi.x());
    const int y0 = clamp_y(lo.y()), y1 = clamp_y(hi.y());
    const std::uint32_t epoch = scratch.next_epoch();
    for (int cy = y0; cy <= y1; ++cy) {
      for (int cx = x0; cx <= x1; ++cx) visit_cell(cx, cy, epoch, scratch, f);
    }
  }

  // Visits the edges bucketed in cells that meet the box [lo, hi] and the wedge
  // {P : n1·(P - apex) <= 0 and n2·(P - apex) <= 0, |P - apex| <= reach} (a beam cone),
  // walking square rings of cells outwards from the apex. Before each ring it calls stop(d), d being a lower bound of the
  // distance from the apex to any edge not yet visited; the walk ends when stop returns true.
  // Returns the last bound checked (infinity when the whole wedge was walked).
  template <class F, class Stop>
  double for_each_in_wedge(const Vec2& apex, const Vec2& lo, const Vec2& hi, const Vec2& n1,
                           const Vec2& n2, double reach, GridScratch& scratch, F&& f,
                           Stop&& stop) const {
    constexpr double kAll = std::numeric_limits<double>::infinity();
    if (nx_ == 0 || misses(lo, hi)) return kAll;
    const int x0 = clamp_x(lo.x()), x1 = clamp_x(hi.x());
    const int y0 = clamp_y(lo.y()), y1 = clamp_y(hi.y());
    // Outside the grid the apex's own cell is meaningless: walk from the nearest cell, and give
    // no distance bound (0) so that stop() cannot end the walk early.
    const bool inside = apex.x() >= origin_.x() && apex.y() >= origin_.y() &&
                        apex.x() < far_.x() && apex.y() < far_.y();
    const int ox = clamp_x(apex.x()), oy = clamp_y(apex.y());
    const int rings = std::max({ox - x0, x1 - ox, oy - y0, y1 - oy});
    const double half = 0.5 * cell_;
    const double slack1 = half * (std::abs(n1.x()) + std::abs(n1.y()));
    const double slack2 = half * (std::abs(n2.x()) + std::abs(n2.y()));
    const std::uint32_t epoch = scratch.next_epoch();
    auto visit_wedge_cell = [&](int cx, int cy) {
      const Vec2 m = origin_ + Vec2((cx + 0.5) * cell_, (cy + 0.5) * cell_) - apex;
      if (n1.dot(m) > slack1 || n2.dot(m) > slack2) return;  // wholly outside the wedge
      const Vec2 gap = (m.cwiseAbs() - Vec2::Constant(half)).cwiseMax(0.0);
      if (gap.squaredNorm() > reach * reach) return;          // wholly beyond reach
      visit_cell(cx, cy, epoch, scratch, f);
    };
    for (int r = 0; r <= rings; ++r) {
      const double bound = (!inside || r == 0) ? 0.0 : (r - 1) * cell_;
      if (inside && r > 0 && stop(bound)) return bound;
      const int ya = oy - r, yb = oy + r, xa = ox - r, xb = ox + r;
      const int cx0 = std::max(xa, x0), cx1 = std::min(xb, x1);
      const int cy0 = std::max(ya + 1, y0), cy1 = std::min(yb - 1, y1);
      if (ya >= y0) {
        for (int cx = cx0; cx <= cx1; ++cx) visit_wedge_cell(cx, ya);
      }
      if (r > 0 && yb <= y1) {
        for (int cx = cx0; cx <= cx1; ++cx) visit_wedge_cell(cx, yb);
      }
      if (xa >= x0) {
        for (int cy = cy0; cy <= cy1; ++cy) visit_wedge_cell(xa, cy);
      }
      if (r > 0 && xb <= x1) {
        for (int cy = cy0; cy <= cy1; ++cy) visit_wedge_cell(xb, cy);
      }
    }
    return kAll;
  }

  double cell() const { return cell_; }
  int columns() const { return nx_; }
  int rows() const { return ny_; }

 private:
  // True when the box [lo, hi] lies wholly outside the grid.
  bool misses(const Vec2& lo, const Vec2& hi) const {
    return hi.x() < origin_.x() || hi.y() < origin_.y() || lo.x() > far_.x() || lo.y() > far_.y();
  }

  // Calls f(index) for each edge bucketed in cell (cx, cy) that the query of `epoch` has not
  // reported yet, and marks it reported.
  template <class F>
  void visit_cell(int cx, int cy, std::uint32_t epoch, GridScratch& scratch, F& f) const {
    const std::size_t c = static_cast<std::size_t>(cy) * nx_ + cx;
    for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
      const std::uint32_t s = items_[k];
      if (scratch.stamp[s] == epoch) continue;
      scratch.stamp[s] = epoch;
      f(s);
    }
  }

  // Cell column (and row, below) of a coordinate, clamped to the grid.
  int clamp_x(double x) const {
    return std::clamp(static_cast<int>(std::floor((x - origin_.x()) / cell_)), 0, nx_ - 1);
  }
  int clamp_y(double y) const {
    return std::clamp(static_cast<int>(std::floor((y - origin_.y()) / cell_)), 0, ny_ - 1);
  }

  Vec2 origin_ = Vec2::Zero();          // lower-left corner of cell (0, 0), m
  Vec2 far_ = Vec2::Zero();             // upper-right corner of the last cell, m
  double cell_ = 0.5;                   // cell side, m
  int nx_ = 0;                          // cells along x
  int ny_ = 0;                          // cells along y
  std::vector<std::uint32_t> start_;    // per cell, first index into items_ (size cells + 1)
  std::vector<std::uint32_t> items_;    // edge indices, cell after cell
};

}  // namespace robuter::sim
