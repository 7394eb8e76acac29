// SPDX-License-Identifier: GPL-3.0-or-later
// Blocked-or-not per heading slice and cell, one bit each, on a PassGrid's bordered indexing.
#pragma once

#include <cstdint>
#include <vector>

#include "modules/planner/lib/geometry.hpp"

namespace robuter::plan {

// S layers that are only ever asked "blocked or not" (the turn-clearance layers): bit k of a
// cell's words is set when slice k is blocked there. Cells are indexed as in a PassGrid of the
// same width (a one-cell border, index = (y + 1) * stride + (x + 1)), so a search reads both
// with one index. Words per cell follow the slice count: one uint32 for up to 32 slices, four
// for 128. Everything (border and unused high bits included) starts blocked.
struct SliceBits {
  int width = 0;                     // cells
  int height = 0;                    // cells
  int stride = 2;                    // cells per stored row (width + 2)
  int slices = 0;                    // layers (bits used per cell)
  int words = 1;                     // uint32 words per stored cell: (slices + 31) / 32
  std::vector<std::uint32_t> bits;   // per stored cell, `words` words; set bit = blocked

  // Why: sized once per map; every bit starts blocked.
  void resize(int w, int h, int s) {
    width = w;
    height = h;
    stride = w + 2;
    slices = s;
    words = s > 0 ? (s + 31) / 32 : 1;
    bits.assign(static_cast<std::size_t>(stride) * static_cast<std::size_t>(h + 2) *
                    static_cast<std::size_t>(words), ~std::uint32_t{0});
  }
  bool empty() const { return slices == 0; }
  bool contains(Cell c) const { return c.x >= 0 && c.y >= 0 && c.x < width && c.y < height; }
  std::uint32_t index(Cell c) const {
    return static_cast<std::uint32_t>((c.y + 1) * stride + (c.x + 1));
  }
  // Why: the search's test, by stored index (as PassGrid::index gives it).
  bool blocked_at(std::uint32_t i, int slice) const {
    const std::uint32_t w = bits[static_cast<std::size_t>(i) * static_cast<std::size_t>(words) +
                                 static_cast<std::size_t>(slice >> 5)];
    return ((w >> (slice & 31)) & 1u) != 0;
  }
  bool blocked(Cell c, int slice) const { return blocked_at(index(c), slice); }
  // Why: the layers' writes (build and incremental update).
  void set_blocked(std::uint32_t i, int slice, bool b) {
    std::uint32_t& w = bits[static_cast<std::size_t>(i) * static_cast<std::size_t>(words) +
                            static_cast<std::size_t>(slice >> 5)];
    const std::uint32_t m = std::uint32_t{1} << (slice & 31);
    w = b ? (w | m) : (w & ~m);
  }
};

}  // namespace robuter::plan
