// SPDX-License-Identifier: GPL-3.0-or-later
// World finalisation: polygon edges, bounds and the spatial grid.
#include "hal/sim/world.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace robuter::sim {

namespace {

constexpr double kOnBoundary = 1e-9;  // a point this near a polygon's edge is on it, not inside, m

// Whether p lies inside the polygon and off its edges.
bool strictly_inside(const Vec2& p, const std::vector<Vec2>& v) {
  if (!point_in_polygon(p, v)) return false;
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (point_segment_distance(p, v[k], v[(k + 1) % v.size()]) <= kOnBoundary) return false;
  }
  return true;
}

// The box of a polygon's vertices.
Box box_of(const std::vector<Vec2>& v) {
  Box b{v.front(), v.front()};
  for (const auto& p : v) {
    b.lo = b.lo.cwiseMin(p);
    b.hi = b.hi.cwiseMax(p);
  }
  return b;
}

}  // namespace

// Each polygon contributes its closing edge too; two-vertex obstacles are a single edge. An edge
// contributes only its parts that lie strictly inside no other polygon: where solids overlap (a
// wall's squared end inside the wall it meets, a box against a wall) the hidden faces are not
// surfaces, and their ends are not corners a beam may find. (Until 2026-12-05 they were: the end
// of a room's wall, flush with a corridor's face, echoed to a ring sensor 68° off that
// face, and the firmware stopped for an obstacle in an open corridor, docs/SIMULATOR.md.)
void World::finalize(double cell) {
  segments_.clear();
  // The solids' bounding boxes, each as its diagonal, bucketed in a SegmentGrid: an edge is
  // tested against the solids near it only (with all pairs, `robuter-sim render` of a world of
  // 8,000 boxes took 1.73 s; so, 0.23 s).
  std::vector<Segment> solids;
  for (std::size_t j = 0; j < obstacles_.size(); ++j) {
    const auto& v = obstacles_[j].vertices;
    if (v.size() < 3) continue;
    const Box b = box_of(v);
    solids.push_back({b.lo, b.hi, static_cast<int>(j)});
  }
  SegmentGrid solid_grid;
  solid_grid.build(solids, cell);
  GridScratch scratch;
  scratch.prepare(solids.size());
  std::vector<double> cuts;  // where the edge crosses a near solid's outline, fractions of it
  std::vector<int> near;     // the solids whose boxes meet the edge's
  // Adds the visible parts of edge (a, b) of obstacle idx.
  auto add_edge = [&](const Vec2& a, const Vec2& b, int idx) {
    const Vec2 ab = b - a;
    const double len = ab.norm();
    if (len <= 0.0) return;
    const Surface kind = obstacles_[static_cast<std::size_t>(idx)].surface;
    const Box eb{a.cwiseMin(b), a.cwiseMax(b)};
    cuts.assign({0.0, 1.0});
    near.clear();
    solid_grid.for_each_near(eb.lo, eb.hi, scratch, [&](std::uint32_t k) {
      const Segment& box = solids[k];
      if (box.obstacle == idx) return;
      if ((eb.lo.array() > box.b.array()).any() || (eb.hi.array() < box.a.array()).any()) return;
      near.push_back(box.obstacle);
      const auto& v = obstacles_[static_cast<std::size_t>(box.obstacle)].vertices;
      for (std::size_t m = 0; m < v.size(); ++m) {
        const Vec2& c = v[m];
        const Vec2 cd = v[(m + 1) % v.size()] - c;
        const double denom = cross(ab, cd);
        if (std::abs(denom) > 1e-12 * len * cd.norm()) {
          const double t = cross(c - a, cd) / denom;
          const double u = cross(c - a, ab) / denom;
          if (u >= -1e-12 && u <= 1.0 + 1e-12 && t > 0.0 && t < 1.0) cuts.push_back(t);
        } else if (std::abs(cross(ab, c - a)) <= kOnBoundary * len) {  // collinear: its ends
          for (const Vec2& e : {c, Vec2(c + cd)}) {
            const double t = (e - a).dot(ab) / (len * len);
            if (t > 0.0 && t < 1.0) cuts.push_back(t);
          }
        }
      }
    });
    if (near.empty()) {
      segments_.push_back({a, b, idx, kind});
      return;
    }
    std::sort(cuts.begin(), cuts.end());
    double open = -1.0;  // start of the visible run being built, or -1
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double t0 = cuts[k], t1 = cuts[k + 1];
      if ((t1 - t0) * len <= kOnBoundary) continue;
      const Vec2 mid = a + 0.5 * (t0 + t1) * ab;
      const bool hidden = std::any_of(near.begin(), near.end(), [&](int j) {
        return strictly_inside(mid, obstacles_[static_cast<std::size_t>(j)].vertices);
      });
      if (!hidden && open < 0.0) open = t0;
      if (hidden && open >= 0.0) {
        segments_.push_back({a + open * ab, a + t0 * ab, idx, kind});
        open = -1.0;
      }
    }
    if (open >= 0.0) segments_.push_back({open == 0.0 ? a : Vec2(a + open * ab), b, idx, kind});
  };
  for (std::size_t i = 0; i < obstacles_.size(); ++i) {
    const auto& v = obstacles_[i].vertices;
    const int idx = static_cast<int>(i);
    if (v.size() == 2) {
      add_edge(v[0], v[1], idx);
      continue;
    }
    for (std::size_t k = 0; k < v.size(); ++k) add_edge(v[k], v[(k + 1) % v.size()], idx);
  }
  if (segments_.empty()) {
    bounds_ = {Vec2::Zero(), Vec2::Zero()};
  } else {
    Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity());
    Vec2 hi = -lo;
    for (const auto& s : segments_) {
      lo = lo.cwiseMin(s.a).cwiseMin(s.b);
      hi = hi.cwiseMax(s.a).cwiseMax(s.b);
    }
    bounds_ = {lo, hi};
  }
  grid_.build(segments_, cell);
}

// Linear scan: used by loaders and tests, never on the periodic path.
int World::obstacle_containing(const Vec2& p) const {
  for (std::size_t i = 0; i < obstacles_.size(); ++i) {
    const auto& v = obstacles_[i].vertices;
    if (v.size() >= 3 && point_in_polygon(p, v)) return static_cast<int>(i);
  }
  return -1;
}

double World::clearance(const Vec2& p) const {
  if (obstacle_containing(p) >= 0) return 0.0;
  double best = std::numeric_limits<double>::infinity();
  for (const auto& s : segments_) best = std::min(best, point_segment_distance(p, s.a, s.b));
  return best;
}

}  // namespace robuter::sim
