// SPDX-License-Identifier: GPL-3.0-or-later
// Building and incrementally updating footprint-dilated C-space layers.
#include "modules/planner/lib/cspace.hpp"

#include <algorithm>

namespace robuter::plan {
namespace {

// Why: the class a searchable cell takes from its cover count and the map.
std::uint8_t class_of(std::uint16_t cover, CellState s) {
  if (cover > 0 || s == CellState::Occupied) return kBlocked;
  return s == CellState::Unknown ? kUnknown : kFree;
}

}  // namespace

void pass_grid_from_map(const OccupancyMap& map, PassGrid& grid) {
  if (grid.width != map.width() || grid.height != map.height()) grid.resize(map.width(), map.height());
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x) grid.set({x, y}, class_of(0, map.state({x, y})));
}

void CSpaceLayer::build(const OccupancyMap& map, FootprintMask mask) {
  mask_ = std::move(mask);
  const int w = map.width();
  const int h = map.height();
  const std::size_t n = map.cell_count();
  cover_.assign(n, 0);
  counted_.assign(n, 0);
  marked_.assign(n, 0);
  grid_.resize(w, h);
  // prefix[y * (w + 1) + x] = occupied cells in row y with column < x.
  std::vector<std::uint32_t> prefix(static_cast<std::size_t>(w + 1) * static_cast<std::size_t>(h), 0);
  for (int y = 0; y < h; ++y) {
    std::uint32_t* row = prefix.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(w + 1);
    for (int x = 0; x < w; ++x) {
      const bool occ = map.state({x, y}) == CellState::Occupied;
      counted_[map.index({x, y})] = occ ? 1 : 0;
      row[x + 1] = row[x] + (occ ? 1u : 0u);
    }
  }
  // Per output row, add each mask run's count of occupied cells (prefix differences); the
  // columns where the run lies fully inside the map need no clamping (a vectorisable loop).
  std::vector<std::uint32_t> acc(static_cast<std::size_t>(w));
  for (int y = 0; y < h; ++y) {
    std::fill(acc.begin(), acc.end(), 0u);
    for (const MaskRun& r : mask_.runs) {
      const int yy = y + r.dy;
      if (yy < 0 || yy >= h) continue;
      const std::uint32_t* row = prefix.data() + static_cast<std::size_t>(yy) * static_cast<std::size_t>(w + 1);
      if (row[w] == 0) continue;  // no obstacle in that row (a fresh, unknown map: every row)
      const int x_in = std::max(0, -r.lo);            // first x with x + lo >= 0
      const int x_out = std::min(w - 1, w - 1 - r.hi);  // last x with x + hi <= w - 1
      auto clamped = [&](int x) {
        const int lo = std::max(x + r.lo, 0);
        const int hi = std::min(x + r.hi, w - 1);
        if (lo <= hi) acc[static_cast<std::size_t>(x)] += row[hi + 1] - row[lo];
      };
      for (int x = 0; x < std::min(x_in, w); ++x) clamped(x);
      for (int x = x_in; x <= x_out; ++x)
        acc[static_cast<std::size_t>(x)] += row[x + r.hi + 1] - row[x + r.lo];
      for (int x = std::max(x_out + 1, x_in); x < w; ++x) clamped(x);
    }
    for (int x = 0; x < w; ++x) {
      const std::uint32_t i = map.index({x, y});
      cover_[i] = static_cast<std::uint16_t>(std::min<std::uint32_t>(acc[static_cast<std::size_t>(x)], 65535));
      grid_.set({x, y}, class_of(cover_[i], map.state_at(i)));
    }
  }
}

// Why: recompute one cell's class and report it if it changed.
void CSpaceLayer::reclass(const OccupancyMap& map, std::uint32_t i, std::vector<ClassChange>* out) {
  const Cell c = map.cell_of_index(i);
  const std::uint32_t g = grid_.index(c);
  const std::uint8_t now = class_of(cover_[i], map.state_at(i));
  const std::uint8_t before = grid_.cls[g];
  if (now == before) return;
  grid_.cls[g] = now;
  if (out && !marked_[i]) {
    marked_[i] = 1;
    out->push_back({g, before});
  }
}

void CSpaceLayer::update(const OccupancyMap& map, std::span<const std::uint32_t> cells,
                         std::vector<ClassChange>* out) {
  const std::size_t first = out ? out->size() : 0;
  const int w = map.width();
  const int h = map.height();
  for (std::uint32_t o : cells) {
    const bool occ = map.state_at(o) == CellState::Occupied;
    if (occ != (counted_[o] != 0)) {
      counted_[o] = occ ? 1 : 0;
      const Cell oc = map.cell_of_index(o);
      for (const MaskRun& r : mask_.runs) {
        const int y = oc.y - r.dy;
        if (y < 0 || y >= h) continue;
        const int lo = std::max(oc.x - r.hi, 0);
        const int hi = std::min(oc.x - r.lo, w - 1);
        for (int x = lo; x <= hi; ++x) {
          const std::uint32_t p = map.index({x, y});
          cover_[p] = static_cast<std::uint16_t>(occ ? cover_[p] + 1 : cover_[p] - 1);
          reclass(map, p, out);
        }
      }
    }
    reclass(map, o, out);  // free <-> unknown changes the class without touching cover
  }
  if (out) {
    // Drop cells that flipped back, and clear the report marks.
    std::size_t keep = first;
    for (std::size_t k = first; k < out->size(); ++k) {
      const ClassChange ch = (*out)[k];
      marked_[map.index(grid_.cell(ch.index))] = 0;
      if (grid_.cls[ch.index] != ch.before) (*out)[keep++] = ch;
    }
    out->resize(keep);
  }
}

}  // namespace robuter::plan
