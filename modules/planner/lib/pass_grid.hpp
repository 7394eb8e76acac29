// SPDX-License-Identifier: GPL-3.0-or-later
// The searchable grid: a cost class per cell with a blocked border, and 8-neighbour tables.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "modules/planner/lib/geometry.hpp"

namespace robuter::plan {

// Cost class of a cell in a searchable grid.
enum CellClass : std::uint8_t {
  kBlocked = 0,  // not traversable (obstacle, expanded obstacle, outside the map)
  kFree = 1,     // known free
  kUnknown = 2,  // never seen; traversable at the unknown cost
};

// A width x height grid of cell classes stored with a one-cell blocked border, so that
// neighbours never need a bounds check. Index = (y + 1) * stride + (x + 1).
struct PassGrid {
  int width = 0;                     // cells
  int height = 0;                    // cells
  int stride = 2;                    // cells per stored row (width + 2)
  std::vector<std::uint8_t> cls;     // CellClass per stored cell, border = kBlocked

  PassGrid() = default;
  PassGrid(int w, int h) { resize(w, h); }

  // Why: sized once per map; everything starts blocked.
  void resize(int w, int h) {
    width = w;
    height = h;
    stride = w + 2;
    cls.assign(static_cast<std::size_t>(stride) * static_cast<std::size_t>(h + 2), kBlocked);
  }
  std::size_t stored() const { return cls.size(); }
  bool contains(Cell c) const { return c.x >= 0 && c.y >= 0 && c.x < width && c.y < height; }
  std::uint32_t index(Cell c) const {
    return static_cast<std::uint32_t>((c.y + 1) * stride + (c.x + 1));
  }
  Cell cell(std::uint32_t i) const {
    const auto s = static_cast<std::uint32_t>(stride);
    return {static_cast<int>(i % s) - 1, static_cast<int>(i / s) - 1};
  }
  std::uint8_t at(Cell c) const { return cls[index(c)]; }
  void set(Cell c, std::uint8_t k) { cls[index(c)] = k; }
};

// The 8 moves. Order is the thesis' (orthogonal first: +y, +x, -y, -x; then the diagonals
// (+1,+1), (+1,-1), (-1,-1), (-1,+1)), which the breadth-first mode keeps.
inline constexpr std::array<int, 8> kMoveDx = {0, 1, 0, -1, 1, 1, -1, -1};
inline constexpr std::array<int, 8> kMoveDy = {1, 0, -1, 0, 1, -1, -1, 1};
inline constexpr int kNoMove = 255;  // "no parent" marker in parent-move arrays

// Why: the index of the move opposite to m (for walking parent pointers backwards).
inline constexpr int opposite_move(int m) { return m < 4 ? (m + 2) & 3 : 4 + ((m - 4 + 2) & 3); }

// Index offsets of the 8 moves in a PassGrid with the given stride, and for a diagonal move
// the two orthogonal side cells that must both be free (no corner cutting).
struct MoveTable {
  std::array<std::int32_t, 8> step{};   // index offset of each move
  std::array<std::int32_t, 8> side_a{}; // diagonal: offset of the side cell along x
  std::array<std::int32_t, 8> side_b{}; // diagonal: offset of the side cell along y

  // Why: computed once per grid width.
  explicit MoveTable(int stride = 2) {
    for (int m = 0; m < 8; ++m) {
      step[m] = kMoveDx[m] + kMoveDy[m] * stride;
      side_a[m] = kMoveDx[m];
      side_b[m] = kMoveDy[m] * stride;
    }
  }
  // Why: the grid move rule in one place: move m from stored cell u in classes `cls` lands on a
  // cell that is not blocked, and a diagonal also needs both side cells not blocked.
  bool passable(const std::uint8_t* cls, std::uint32_t u, int m) const {
    if (cls[u + static_cast<std::uint32_t>(step[m])] == kBlocked) return false;
    return m < 4 || (cls[u + static_cast<std::uint32_t>(side_a[m])] != kBlocked &&
                     cls[u + static_cast<std::uint32_t>(side_b[m])] != kBlocked);
  }
};

// Per-class cost multipliers: a move of length L between cells of classes a and b costs
// L * (mult[a] + mult[b]) / 2, symmetric so forward and reverse searches agree.
struct CostModel {
  double unknown_cost = 1.0;  // multiplier (>= 1) for unknown cells; 1 = the thesis (free)

  // Why: table of each move's cost by the classes of its two cells, built once per search.
  std::array<std::array<std::array<double, 3>, 3>, 8> table() const {
    std::array<std::array<std::array<double, 3>, 3>, 8> t{};
    const double u = unknown_cost < 1.0 ? 1.0 : unknown_cost;
    const std::array<double, 3> mult = {0.0, 1.0, u};
    for (int m = 0; m < 8; ++m) {
      const double len = m < 4 ? 1.0 : kSqrt2;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) t[m][a][b] = len * 0.5 * (mult[a] + mult[b]);
    }
    return t;
  }
};

}  // namespace robuter::plan
