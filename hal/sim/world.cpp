// SPDX-License-Identifier: GPL-3.0-or-later
// World finalisation: polygon edges, bounds and the spatial grid.
#include "hal/sim/world.hpp"

#include <limits>

namespace robuter::sim {

// Each polygon contributes its closing edge too; two-vertex obstacles are a single edge.
void World::finalize(double cell) {
  segments_.clear();
  for (std::size_t i = 0; i < obstacles_.size(); ++i) {
    const auto& v = obstacles_[i].vertices;
    const int idx = static_cast<int>(i);
    if (v.size() == 2) {
      segments_.push_back({v[0], v[1], idx});
      continue;
    }
    for (std::size_t k = 0; k < v.size(); ++k) {
      const Vec2& a = v[k];
      const Vec2& b = v[(k + 1) % v.size()];
      if ((a - b).squaredNorm() > 0.0) segments_.push_back({a, b, idx});
    }
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

}  // namespace robuter::sim
