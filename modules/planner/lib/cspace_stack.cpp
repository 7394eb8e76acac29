// SPDX-License-Identifier: GPL-3.0-or-later
// The layers' shared occupancy table and per-cell marks.
#include "modules/planner/lib/cspace_stack.hpp"

#include <algorithm>
#include <bit>

namespace robuter::plan {
namespace {

// Why: out[p] |= r[p + s] for the bits p of `nout` words; r holds `nr` words and its bits
// outside [0, 64 nr) read as 0.
void or_shifted(std::uint64_t* out, int nout, const std::uint64_t* r, int nr, int s) {
  const int q = s >= 0 ? s >> 6 : -((-s + 63) >> 6);  // floor(s / 64)
  const int b = s - q * 64;                            // 0..63
  for (int j = 0; j < nout; ++j) {
    const int i = j + q;
    if (i + 1 < 0) continue;
    if (i >= nr) break;
    std::uint64_t v = i >= 0 ? r[i] >> b : 0;
    if (b != 0 && i + 1 < nr) v |= r[i + 1] << (64 - b);
    out[j] |= v;
  }
}

}  // namespace

void CSpaceStack::reset(const OccupancyMap& map) {
  w_ = map.width();
  h_ = map.height();
  stride_ = static_cast<std::size_t>(w_) + 1;
  sat_.assign(stride_ * (static_cast<std::size_t>(h_) + 1), 0);
  marks_.assign(map.cell_count(), 0);
  wpr_ = std::max(1, (w_ + 63) / 64);
  spans_.assign(static_cast<std::size_t>(kLevels) * static_cast<std::size_t>(h_) * static_cast<std::size_t>(wpr_ + 1), 0);
  row_any_.assign(static_cast<std::size_t>(h_), 0);
  row_dirty_.assign(static_cast<std::size_t>(h_), 0);
  base_.assign(map.cell_count(), kFree);
  scratch_.assign(static_cast<std::size_t>(wpr_), 0);
  window_.assign(kWindowWords, 0);
  windows_ = 0;
  rebuild(map);
}

void CSpaceStack::rebuild(const OccupancyMap& map) {
  rebuild_table(map, 0);
  for (int y = 0; y < h_; ++y) rebuild_row(map, y);
}

// Why: O(cells) additions from row y0 down (the rows above keep their counts), cheaper than any
// per-cell upkeep once a sync changed a few hundred.
void CSpaceStack::rebuild_table(const OccupancyMap& map, int y0) {
  for (int y = y0; y < h_; ++y) {
    const std::uint16_t* above = sat_.data() + static_cast<std::size_t>(y) * stride_;
    std::uint16_t* row = sat_.data() + static_cast<std::size_t>(y + 1) * stride_;
    std::uint16_t run = 0;  // occupied cells of this row left of x, mod 2^16
    const std::uint32_t base = static_cast<std::uint32_t>(y) * static_cast<std::uint32_t>(w_);
    for (int x = 0; x < w_; ++x) {
      run = static_cast<std::uint16_t>(run + (map.state_at(base + static_cast<std::uint32_t>(x)) == CellState::Occupied));
      row[x + 1] = static_cast<std::uint16_t>(above[x + 1] + run);
    }
  }
}

// Why: one row's bitset, its span levels (level k = level k-1 OR level k-1 shifted by 2^(k-1))
// and its cells' own classes. A row is stored with one word of empty cells on its left, so
// that a span starting up to 64 cells left of the map still reads the cells it covers inside.
void CSpaceStack::rebuild_row(const OccupancyMap& map, int y) {
  const int n = wpr_ + 1;
  const std::size_t level = static_cast<std::size_t>(h_) * static_cast<std::size_t>(n);
  std::uint64_t* bits = spans_.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(n);
  for (int k = 0; k < kLevels; ++k) std::fill(bits + static_cast<std::size_t>(k) * level, bits + static_cast<std::size_t>(k) * level + n, 0);
  const std::uint32_t base = static_cast<std::uint32_t>(y) * static_cast<std::uint32_t>(w_);
  bool any = false;
  for (int x = 0; x < w_; ++x) {
    const CellState s = map.state_at(base + static_cast<std::uint32_t>(x));
    base_[base + static_cast<std::uint32_t>(x)] = own_class(s);
    if (s == CellState::Occupied) {
      bits[1 + (x >> 6)] |= std::uint64_t{1} << (x & 63);
      any = true;
    }
  }
  row_any_[static_cast<std::size_t>(y)] = any ? 1 : 0;
  if (!any) return;
  for (int k = 1; k < kLevels; ++k) {
    const std::uint64_t* prev = bits + static_cast<std::size_t>(k - 1) * level;
    std::uint64_t* cur = bits + static_cast<std::size_t>(k) * level;
    for (int j = 0; j < n; ++j) cur[j] = prev[j];
    or_shifted(cur, n, prev, n, 1 << (k - 1));
  }
}

void CSpaceStack::dilate_row(std::span<const MaskRun> runs, int y, std::uint64_t* out) const {
  const int n = wpr_ + 1;
  const std::size_t level = static_cast<std::size_t>(h_) * static_cast<std::size_t>(n);
  constexpr int kPiece = 1 << (kLevels - 1);  // widest run piece covered by two spans (64 cells)
  for (const MaskRun& r : runs) {
    const int yy = y + r.dy;
    if (yy < 0 || yy >= h_ || !row_any_[static_cast<std::size_t>(yy)]) continue;
    const std::uint64_t* row = spans_.data() + static_cast<std::size_t>(yy) * static_cast<std::size_t>(n);
    // Cell p meets the run when an occupied cell lies in [p + lo, p + hi]: cover the run by
    // pieces of at most kPiece cells, each by two overlapping spans of 2^k cells. A span that
    // starts more than 64 cells left of the map ends left of it too (a piece is at most 64
    // cells), so reading it as empty is exact.
    for (int s = r.lo; s <= r.hi; s += kPiece) {
      const int e = std::min(s + kPiece - 1, r.hi);
      const int k = std::bit_width(static_cast<unsigned>(e - s + 1)) - 1;
      const std::uint64_t* lv = row + static_cast<std::size_t>(k) * level;
      or_shifted(out, wpr_, lv, n, s + 64);
      const int s2 = e - (1 << k) + 1;
      if (s2 != s) or_shifted(out, wpr_, lv, n, s2 + 64);
    }
  }
  // Spans read past the width only hold empty cells, but a shift can bring the last word's
  // unused bits in from the padding: clear them.
  if ((w_ & 63) != 0) out[wpr_ - 1] &= (std::uint64_t{1} << (w_ & 63)) - 1;
}

std::uint32_t CSpaceStack::begin_sync(const OccupancyMap& map, std::span<const std::uint32_t> cells) {
  // Only the rows holding a changed cell are retaken (their bits, spans and classes), and the
  // table from the first row whose occupancy changed.
  int first_moved = h_, y_lo = h_, y_hi = -1;
  std::uint32_t lowered = 0;
  for (std::uint32_t o : cells) {
    const Cell c = map.cell_of_index(o);
    const bool occ = map.state_at(o) == CellState::Occupied;
    const bool was = occupied(c.x, c.y);
    const CellChange k = occ == was ? kRelabelled : occ ? kRaised : kLowered;
    marks_[o] = static_cast<std::uint8_t>((marks_[o] & ~kKindBits) | k);
    lowered += k == kLowered ? 1 : 0;
    row_dirty_[static_cast<std::size_t>(c.y)] = 1;
    y_lo = std::min(y_lo, c.y);
    y_hi = std::max(y_hi, c.y);
    if (occ != was) first_moved = std::min(first_moved, c.y);
  }
  if (first_moved < h_) rebuild_table(map, first_moved);
  for (int y = y_lo; y <= y_hi; ++y) {
    if (!row_dirty_[static_cast<std::size_t>(y)]) continue;
    row_dirty_[static_cast<std::size_t>(y)] = 0;
    rebuild_row(map, y);
  }
  return lowered;
}

void CSpaceStack::end_sync(std::span<const std::uint32_t> cells) {
  for (std::uint32_t o : cells) marks_[o] = static_cast<std::uint8_t>(marks_[o] & ~kKindBits);
}

}  // namespace robuter::plan
