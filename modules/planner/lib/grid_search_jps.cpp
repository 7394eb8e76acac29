// SPDX-License-Identifier: GPL-3.0-or-later
// Jump point search without corner cutting: the optimal mode's engine for uniform costs.
#include <algorithm>
#include <limits>

#include "modules/planner/lib/grid_search.hpp"

namespace robuter::plan {
namespace {

// The class array seen by the jumps: a cell is walkable when its class is not kBlocked.
struct Jumper {
  const std::uint8_t* cls;  // PassGrid classes (blocked border included)
  std::int32_t sn;          // stride: index offset of one row
  std::uint32_t goal;       // goal index (a jump point by definition)

  bool ok(std::uint32_t i) const { return cls[i] != kBlocked; }

  // Why: run along a row from u (exclusive); stop at the goal, at a blocked cell (no jump
  // point), or where a cell above/below becomes reachable only through this row: it is
  // walkable and the cell behind it (against the run) is not.
  std::uint32_t horizontal(std::uint32_t u, std::int32_t dx) const {
    const auto up = static_cast<std::uint32_t>(sn), step = static_cast<std::uint32_t>(dx);
    for (std::uint32_t v = u + step;; v += step) {
      if (!ok(v)) return GridSearch::kNil;
      if (v == goal) return v;
      if ((ok(v + up) && !ok(v - step + up)) || (ok(v - up) && !ok(v - step - up))) return v;
    }
  }

  // Why: the same along a column (dy = +1 or -1).
  std::uint32_t vertical(std::uint32_t u, std::int32_t dy) const {
    const auto step = static_cast<std::uint32_t>(dy * sn);
    for (std::uint32_t v = u + step;; v += step) {
      if (!ok(v)) return GridSearch::kNil;
      if (v == goal) return v;
      if ((ok(v + 1) && !ok(v + 1 - step)) || (ok(v - 1) && !ok(v - 1 - step))) return v;
    }
  }

  // Why: a diagonal run; every step needs both side cells (no corner cutting); a cell is a
  // jump point if a straight run from it along either component finds one.
  std::uint32_t diagonal(std::uint32_t u, std::int32_t dx, std::int32_t dy) const {
    const auto sx = static_cast<std::uint32_t>(dx), sy = static_cast<std::uint32_t>(dy * sn);
    for (std::uint32_t v = u;;) {
      if (!ok(v + sx) || !ok(v + sy)) return GridSearch::kNil;
      v += sx + sy;
      if (!ok(v)) return GridSearch::kNil;
      if (v == goal) return v;
      if (horizontal(v, dx) != GridSearch::kNil || vertical(v, dy) != GridSearch::kNil) return v;
    }
  }

  // Why: one direction's jump.
  std::uint32_t jump(std::uint32_t u, std::int32_t dx, std::int32_t dy) const {
    if (dx != 0 && dy != 0) return diagonal(u, dx, dy);
    return dx != 0 ? horizontal(u, dx) : vertical(u, dy);
  }
};

int sign(int v) { return (v > 0) - (v < 0); }

}  // namespace

PlanResult GridSearch::astar_jps(const PassGrid& grid, std::uint32_t s, std::uint32_t t,
                                 const CostModel& costs) {
  const MoveTable mt(grid.stride);
  const std::uint8_t* cls = grid.cls.data();
  std::uint32_t* mark = mark_.data();
  double* g = g_.data();
  std::uint32_t* from = from_.data();
  const std::uint32_t seen = gen_ << 1, closed = seen | 1u;
  const auto stride = static_cast<std::uint32_t>(grid.stride);
  const auto sn = static_cast<std::int32_t>(stride);
  const int tx = static_cast<int>(t % stride);
  const int ty = static_cast<int>(t / stride);
  const Jumper jumper{cls, sn, t};
  PlanResult r;

  open_.clear();
  mark[s] = seen;
  g[s] = 0.0;
  from[s] = kNil;
  {
    const double h = octile(static_cast<int>(s % stride) - tx, static_cast<int>(s / stride) - ty);
    open_.push(s, h, static_cast<float>(h));
  }
  bool found = false;
  while (!open_.empty()) {
    const std::uint32_t u = open_.pop().node;
    mark[u] = closed;
    ++r.expanded;
    if (u == t) {
      found = true;
      break;
    }
    const int ux = static_cast<int>(u % stride);
    const int uy = static_cast<int>(u / stride);
    const double gu = g[u];
    auto ok = [&](int dx, int dy) { return cls[u + static_cast<std::uint32_t>(dx + dy * sn)] != kBlocked; };
    // Directions to search from u (pruned by the direction u was reached in).
    std::int32_t dirs[8][2];
    int nd = 0;
    auto add = [&](int dx, int dy) {
      dirs[nd][0] = dx;
      dirs[nd][1] = dy;
      ++nd;
    };
    if (from[u] == kNil) {
      for (int m = 0; m < 8; ++m) add(kMoveDx[m], kMoveDy[m]);
    } else {
      const int px = static_cast<int>(from[u] % stride), py = static_cast<int>(from[u] / stride);
      const int dx = sign(ux - px), dy = sign(uy - py);
      if (dx != 0 && dy != 0) {
        add(dx, 0);
        add(0, dy);
        add(dx, dy);
      } else if (dx != 0) {
        add(dx, 0);
        for (int side : {1, -1})
          if (ok(0, side) && !ok(-dx, side)) {  // forced
            add(0, side);
            add(dx, side);
          }
      } else {
        add(0, dy);
        for (int side : {1, -1})
          if (ok(side, 0) && !ok(side, -dy)) {  // forced
            add(side, 0);
            add(side, dy);
          }
      }
    }
    for (int k = 0; k < nd; ++k) {
      const std::int32_t dx = dirs[k][0], dy = dirs[k][1];
      const std::uint32_t j = jumper.jump(u, dx, dy);
      if (j == kNil) continue;
      const int jx = static_cast<int>(j % stride), jy = static_cast<int>(j / stride);
      const double ng = gu + octile(jx - ux, jy - uy);
      const std::uint32_t mj = mark[j];
      if (mj == closed) continue;
      const double h = octile(jx - tx, jy - ty);
      if (mj != seen) {
        mark[j] = seen;
        g[j] = ng;
        from[j] = u;
        open_.push(j, ng + h, static_cast<float>(h));
      } else if (ng < g[j]) {
        g[j] = ng;
        from[j] = u;
        open_.decrease(j, ng + h, static_cast<float>(h));
      }
    }
  }
  if (!found) return r;  // Unreachable
  // Expand the jump points into unit moves (parent_), then build the cell path as usual.
  for (std::uint32_t v = t; from[v] != kNil;) {
    const std::uint32_t p = from[v];
    const int dx = sign(static_cast<int>(v % stride) - static_cast<int>(p % stride));
    const int dy = sign(static_cast<int>(v / stride) - static_cast<int>(p / stride));
    int m = 0;
    while (kMoveDx[m] != dx || kMoveDy[m] != dy) ++m;
    for (std::uint32_t c = v; c != p; c -= static_cast<std::uint32_t>(mt.step[m]))
      parent_[c] = static_cast<std::uint8_t>(m);
    v = p;
  }
  r.status = PlanStatus::Found;
  build_path(grid, mt, s, t, r, costs);
  return r;
}

}  // namespace robuter::plan
