// SPDX-License-Identifier: GPL-3.0-or-later
// Building and incrementally updating footprint-dilated C-space layers.
#include "modules/planner/lib/cspace.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

namespace robuter::plan {
namespace {

// Why: the class a searchable cell takes from its cover count and the map.
std::uint8_t class_of(std::uint16_t cover, CellState s) {
  return cover > 0 ? std::uint8_t{kBlocked} : own_class(s);
}

// A class layer's own PassGrid: writes report each changed cell (once per update) with its
// class before, when asked.
struct ClassStore {
  static constexpr bool kClasses = true;  // free <-> unknown matters
  PassGrid& grid;                         // the layer's classes

  std::uint32_t index(Cell c) const { return grid.index(c); }
  bool blocked(std::uint32_t g) const { return grid.cls[g] == kBlocked; }
  // Why: a full build's row: the cells' own classes, then blocked where `bits` are set.
  void put_row(int y, const std::uint64_t* bits, const std::uint8_t* base, int w) {
    std::uint8_t* dst = grid.cls.data() + grid.index({0, y});
    std::memcpy(dst, base, static_cast<std::size_t>(w));
    for (int j = 0; j * 64 < w; ++j)
      for (std::uint64_t v = bits[j]; v != 0; v &= v - 1) dst[j * 64 + std::countr_zero(v)] = kBlocked;
  }
  void put(std::uint32_t g, std::uint8_t now) { grid.cls[g] = now; }
  // Why: write one cell's class and report it (once per update) if it changed.
  void set(CSpaceStack& stack, std::uint32_t i, std::uint32_t g, std::uint8_t now,
           std::vector<ClassChange>* out) {
    const std::uint8_t before = grid.cls[g];
    if (now == before) return;
    grid.cls[g] = now;
    if (out && stack.mark_reported(i)) out->push_back({g, before});
  }
};

// One slice of a SliceBits: only "blocked or not" is kept, nothing is reported. Holds its word
// and bit and a raw pointer so that the update's inner loop stays as small as a class layer's.
struct BitStore {
  static constexpr bool kClasses = false;  // free <-> unknown changes nothing here
  std::uint32_t* data;                     // SliceBits::bits
  std::size_t words;                       // words per stored cell
  std::size_t word;                        // this slice's word within a cell's
  std::uint32_t bit;                       // this slice's bit within that word
  int stride;                              // stored cells per row

  BitStore(SliceBits& bits, int slice)
      : data(bits.bits.data()), words(static_cast<std::size_t>(bits.words)),
        word(static_cast<std::size_t>(slice >> 5)), bit(std::uint32_t{1} << (slice & 31)),
        stride(bits.stride) {}
  std::uint32_t index(Cell c) const { return static_cast<std::uint32_t>((c.y + 1) * stride + (c.x + 1)); }
  bool blocked(std::uint32_t g) const { return (data[g * words + word] & bit) != 0; }
  void put(std::uint32_t g, std::uint8_t now) {
    std::uint32_t& w = data[g * words + word];
    w = (w & ~bit) | (now == kBlocked ? bit : 0u);
  }
  // Why: as ClassStore::put_row: the slice's bit of each cell of row y (blocked by the
  // footprint, or by the cell's own obstacle).
  void put_row(int y, const std::uint64_t* bits, const std::uint8_t* base, int w) {
    std::uint32_t* cell = data + (static_cast<std::size_t>((y + 1) * stride + 1)) * words + word;
    for (int x = 0; x < w; ++x, cell += words) {
      const bool b = ((bits[x >> 6] >> (x & 63)) & 1u) != 0 || base[x] == kBlocked;
      *cell = (*cell & ~bit) | (b ? bit : 0u);
    }
  }
  // Why: as ClassStore::set, without classes or reports.
  void set(CSpaceStack&, std::uint32_t, std::uint32_t g, std::uint8_t now, std::vector<ClassChange>*) {
    put(g, now);
  }
};

}  // namespace

void pass_grid_from_map(const OccupancyMap& map, PassGrid& grid) {
  if (grid.width != map.width() || grid.height != map.height()) grid.resize(map.width(), map.height());
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x) grid.set({x, y}, class_of(0, map.state({x, y})));
}

void CSpaceLayer::build(const OccupancyMap& map, FootprintMask mask) {
  CSpaceStack stack;
  stack.reset(map);
  build(stack, map, std::move(mask));
}

void CSpaceLayer::build(const CSpaceStack& stack, const OccupancyMap& map, FootprintMask mask) {
  mask_ = std::move(mask);
  index_mask();
  grid_.resize(map.width(), map.height());
  rebuild(stack, map);
}

void CSpaceLayer::build_bits(const OccupancyMap& map, FootprintMask mask, SliceBits& bits, int slice) {
  CSpaceStack stack;
  stack.reset(map);
  build_bits(stack, map, std::move(mask), bits, slice);
}

void CSpaceLayer::build_bits(const CSpaceStack& stack, const OccupancyMap& map, FootprintMask mask,
                             SliceBits& bits, int slice) {
  mask_ = std::move(mask);
  index_mask();
  grid_ = PassGrid{};
  rebuild_bits(stack, map, bits, slice);
}

// Why: every cell of the map once, a row at a time: the row's dilation by the mask from the
// stack's span table (two shifted word ORs per mask run), then the row written through `store`.
template <class Store>
void CSpaceLayer::fill(const CSpaceStack& stack, const OccupancyMap& map, Store& store) const {
  const int w = map.width();
  const int words = stack.row_words();
  std::uint64_t* row = stack.scratch();
  for (int y = 0; y < map.height(); ++y) {
    std::fill(row, row + words, std::uint64_t{0});
    stack.dilate_row(mask_.runs, y, row);
    store.put_row(y, row, stack.base_row(y), w);
  }
}

void CSpaceLayer::rebuild(const CSpaceStack& stack, const OccupancyMap& map) {
  ClassStore store{grid_};
  fill(stack, map, store);
}

void CSpaceLayer::rebuild_bits(const CSpaceStack& stack, const OccupancyMap& map, SliceBits& bits, int slice) const {
  BitStore store{bits, slice};
  fill(stack, map, store);
}

// Why: the bounding box of the mask and of each band of kBandRuns runs, for meets().
void CSpaceLayer::index_mask() {
  auto box_of = [&](std::size_t i0, std::size_t i1) {
    Band b{i0, i1, mask_.runs[i0].lo, mask_.runs[i0].dy, mask_.runs[i0].hi, mask_.runs[i0].dy, false};
    for (std::size_t i = i0; i < i1; ++i) {
      const MaskRun& r = mask_.runs[i];
      b.x0 = std::min(b.x0, r.lo);
      b.x1 = std::max(b.x1, r.hi);
      b.y0 = std::min(b.y0, r.dy);
      b.y1 = std::max(b.y1, r.dy);
    }
    return b;
  };
  // Each box's count is exact below 65,536 cells; a larger box is not used (its runs are).
  auto exact = [](const Band& b) { return static_cast<std::int64_t>(b.x1 - b.x0 + 1) * (b.y1 - b.y0 + 1) < 65536; };
  bands_.clear();
  box_ = Band{};
  box_exact_ = false;
  if (mask_.runs.empty()) return;
  box_ = box_of(0, mask_.runs.size());
  box_exact_ = exact(box_);
  for (std::size_t i = 0; i < mask_.runs.size(); i += kBandRuns) {
    Band b = box_of(i, std::min(i + kBandRuns, mask_.runs.size()));
    b.exact = exact(b);
    bands_.push_back(b);
  }
  index_core();
}

// Why: a re-test after a freed cell (update_in) mostly finds the cell still blocked by the rest
// of the obstacle it was part of; an obstacle anywhere in a box the mask wholly holds says so in
// one table count instead of the bands' runs. The largest such box (by cells): over the mask's
// bounding box, the largest rectangle under each row's histogram of covered columns.
void CSpaceLayer::index_core() {
  core_valid_ = false;
  if (mask_.runs.empty()) return;
  const int bw = box_.x1 - box_.x0 + 1;
  const int bh = box_.y1 - box_.y0 + 1;
  if (static_cast<std::int64_t>(bw) * bh >= 65536) return;  // the table's counts are exact below that
  std::vector<std::uint8_t> in(static_cast<std::size_t>(bw) * static_cast<std::size_t>(bh), 0);
  for (const MaskRun& r : mask_.runs)
    for (int x = r.lo; x <= r.hi; ++x)
      in[static_cast<std::size_t>(r.dy - box_.y0) * static_cast<std::size_t>(bw) + static_cast<std::size_t>(x - box_.x0)] = 1;
  std::vector<int> height(static_cast<std::size_t>(bw), 0);
  std::int64_t best = 0;
  for (int y = 0; y < bh; ++y) {
    for (int x = 0; x < bw; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(bw) + static_cast<std::size_t>(x);
      height[static_cast<std::size_t>(x)] = in[i] ? height[static_cast<std::size_t>(x)] + 1 : 0;
    }
    // Rows y - h + 1 .. y, columns [x0, x1]: the widest run of columns at least h high, for each
    // column's own height h (O(bw^2) per row: masks are a few dozen cells across).
    for (int x = 0; x < bw; ++x) {
      const int h = height[static_cast<std::size_t>(x)];
      if (h == 0) continue;
      int x0 = x, x1 = x;
      while (x0 > 0 && height[static_cast<std::size_t>(x0 - 1)] >= h) --x0;
      while (x1 + 1 < bw && height[static_cast<std::size_t>(x1 + 1)] >= h) ++x1;
      const std::int64_t area = static_cast<std::int64_t>(x1 - x0 + 1) * h;
      if (area > best) {
        best = area;
        core_ = Band{0, 0, box_.x0 + x0, box_.y0 + y - h + 1, box_.x0 + x1, box_.y0 + y, true};
        core_valid_ = true;
      }
    }
  }
}

// Why: whether the footprint at (x, y) meets an occupied cell: the mask's bounding box settles
// the cells in open space at once, each band's box skips its runs when empty, and the first
// run holding an obstacle ends the test.
bool CSpaceLayer::meets(const CSpaceStack& stack, int x, int y) const {
  if (stack.occupied(x, y)) return true;
  if (core_valid_ && stack.count(x + core_.x0, y + core_.y0, x + core_.x1, y + core_.y1) != 0) return true;
  if (box_exact_ && stack.count(x + box_.x0, y + box_.y0, x + box_.x1, y + box_.y1) == 0) return false;
  for (const Band& b : bands_) {
    if (b.exact && stack.count(x + b.x0, y + b.y0, x + b.x1, y + b.y1) == 0) continue;
    for (std::size_t i = b.first; i < b.last; ++i) {
      const MaskRun& r = mask_.runs[i];
      if (stack.any_in_row(y + r.dy, x + r.lo, x + r.hi)) return true;
    }
  }
  return false;
}

[[gnu::flatten]] void CSpaceLayer::update(CSpaceStack& stack, const OccupancyMap& map, std::span<const std::uint32_t> cells,
                         std::vector<ClassChange>* out) {
  ClassStore store{grid_};
  update_in(store, stack, map, cells, out);
}

// Flattened: the update's inner loop (the visit lambda, the store's writes) inlined into one
// function, as the compiler chose before the row builds were added (2.6x slower when it did not).
[[gnu::flatten]] void CSpaceLayer::update_bits(CSpaceStack& stack, const OccupancyMap& map, std::span<const std::uint32_t> cells,
                              SliceBits& bits, int slice) {
  BitStore store{bits, slice};
  update_in(store, stack, map, cells, nullptr);
}

// Why: new obstacles close together (the block a scan finds ahead) block the cells of a small
// window around them. By runs, each cell near a 10 x 10 block is visited once per raised row
// under its footprint (ten times); here the spans every (raised run, mask run) pair covers are
// first ORed into the window's bits (CSpaceStack::window(): a few words per row), and each cell
// of their union is visited once. Taken when the union's visits are estimated fewer and the
// window fits; false (nothing done) otherwise, and the caller goes by runs. The same cells are
// blocked either way.
template <class Store>
bool CSpaceLayer::block_raised_by_window(Store& store, CSpaceStack& stack, const OccupancyMap& map,
                                         std::span<const std::uint32_t> cells,
                                         std::vector<ClassChange>* out) const {
  if (mask_.runs.empty()) return false;
  const int w = map.width();
  const int h = map.height();
  int bx0 = w, by0 = h, bx1 = -1, by1 = -1;
  std::int64_t raised = 0, runs = 0;
  for (std::uint32_t o : cells) {
    if (stack.kind(o) != kRaised) continue;
    const Cell c = map.cell_of_index(o);
    bx0 = std::min(bx0, c.x);
    bx1 = std::max(bx1, c.x);
    by0 = std::min(by0, c.y);
    by1 = std::max(by1, c.y);
    ++raised;
    if (!(c.x > 0 && stack.kind(o - 1) == kRaised)) ++runs;
  }
  if (raised == 0) return false;
  const int x_lo = std::max(bx0 - box_.x1, 0);
  const int x_hi = std::min(bx1 - box_.x0, w - 1);
  const int y_lo = std::max(by0 - box_.y1, 0);
  const int y_hi = std::min(by1 - box_.y0, h - 1);
  if (x_lo > x_hi || y_lo > y_hi) return false;
  const int x0 = x_lo & ~63;  // the window's first column (word-aligned)
  const int nw = ((x_hi - x0) >> 6) + 1;  // words per window row
  const int rows = y_hi - y_lo + 1;
  std::int64_t mask_cells = 0;
  for (const MaskRun& r : mask_.runs) mask_cells += r.hi - r.lo + 1;
  const auto mask_rows = static_cast<std::int64_t>(mask_.runs.size());
  // Visits by runs (each run's spans) against the window's (its area at most, plus one range
  // OR per pair, about a visit each).
  const std::int64_t by_runs = runs * mask_cells + (raised - runs) * mask_rows;
  const std::int64_t by_window = static_cast<std::int64_t>(rows) * (x_hi - x_lo + 1) + runs * mask_rows;
  if (by_window >= by_runs) return false;
  std::uint64_t* win = stack.window(static_cast<std::size_t>(rows) * static_cast<std::size_t>(nw));
  if (win == nullptr) return false;  // larger than the stack's window: by runs
  std::fill_n(win, static_cast<std::size_t>(rows) * static_cast<std::size_t>(nw), std::uint64_t{0});
  for (std::uint32_t o : cells) {
    if (stack.kind(o) != kRaised) continue;
    const Cell oc = map.cell_of_index(o);
    if (oc.x > 0 && stack.kind(o - 1) == kRaised) continue;  // not the first of its run
    int last = oc.x;
    while (last + 1 < w && stack.kind(o + static_cast<std::uint32_t>(last + 1 - oc.x)) == kRaised) ++last;
    for (const MaskRun& r : mask_.runs) {
      const int y = oc.y - r.dy;
      if (y < y_lo || y > y_hi) continue;
      const int lo = std::max(oc.x - r.hi, x_lo) - x0;
      const int hi = std::min(last - r.lo, x_hi) - x0;
      if (lo > hi) continue;
      std::uint64_t* wr = win + static_cast<std::size_t>(y - y_lo) * static_cast<std::size_t>(nw);
      const int jl = lo >> 6;
      const int jh = hi >> 6;
      const std::uint64_t first = ~std::uint64_t{0} << (lo & 63);
      const std::uint64_t end = (hi & 63) == 63 ? ~std::uint64_t{0} : (std::uint64_t{1} << ((hi & 63) + 1)) - 1;
      if (jl == jh) {
        wr[jl] |= first & end;
      } else {
        wr[jl] |= first;
        for (int j = jl + 1; j < jh; ++j) wr[j] = ~std::uint64_t{0};
        wr[jh] |= end;
      }
    }
    for (int x = oc.x; x <= last; ++x) {  // the run's cells themselves (their own obstacle)
      const std::uint32_t g = store.index({x, oc.y});
      if (!store.blocked(g)) store.set(stack, o + static_cast<std::uint32_t>(x - oc.x), g, kBlocked, out);
    }
  }
  for (int y = y_lo; y <= y_hi; ++y) {
    const std::uint64_t* wr = win + static_cast<std::size_t>(y - y_lo) * static_cast<std::size_t>(nw);
    const std::uint32_t row = static_cast<std::uint32_t>(y) * static_cast<std::uint32_t>(w);
    for (int j = 0; j < nw; ++j)
      for (std::uint64_t v = wr[j]; v != 0; v &= v - 1) {
        const int x = x0 + j * 64 + std::countr_zero(v);
        const std::uint32_t g = store.index({x, y});
        if (!store.blocked(g)) store.set(stack, row + static_cast<std::uint32_t>(x), g, kBlocked, out);
      }
  }
  return true;
}

// Why: one update, written through `store`; `out` only with a class store.
template <class Store>
void CSpaceLayer::update_in(Store& store, CSpaceStack& stack, const OccupancyMap& map,
                            std::span<const std::uint32_t> cells, std::vector<ClassChange>* out) const {
  const std::size_t first = out ? out->size() : 0;
  const int w = map.width();
  const int h = map.height();
  // Blocks first, then the re-tests against the final occupancy, then the relabels: each step
  // writes what the final occupancy and states say, so the order only decides the work.
  // A bit layer skips the relabels: they never change whether a cell is blocked.
  const bool raised_done = block_raised_by_window(store, stack, map, cells, out);
  for (const CellChange pass : {kRaised, kLowered, kRelabelled}) {
    if (!Store::kClasses && pass == kRelabelled) break;
    if (pass == kRaised && raised_done) continue;
    for (std::uint32_t o : cells) {
      if (stack.kind(o) != pass) continue;
      const Cell oc = map.cell_of_index(o);
      if (pass == kRelabelled) {
        const std::uint32_t g = store.index(oc);
        if (!store.blocked(g)) store.set(stack, o, g, class_of(0, map.state_at(o)), out);
        continue;
      }
      // The cells p whose footprint covers o: p = o - (dx, dy) for each mask offset; and o
      // itself (blocked by its own obstacle whether or not the mask holds (0, 0)).
      auto visit = [&](int x, int y) {
        const std::uint32_t i = static_cast<std::uint32_t>(y) * static_cast<std::uint32_t>(w) + static_cast<std::uint32_t>(x);
        const std::uint32_t g = store.index({x, y});
        if (pass == kRaised) {
          if (!store.blocked(g)) store.set(stack, i, g, kBlocked, out);
        } else if (store.blocked(g) && stack.mark_checked(i)) {
          // Re-tested once per update: a cell still blocked is not tested again for the next
          // freed cell under its footprint.
          if (!meets(stack, x, y)) store.set(stack, i, g, class_of(0, map.state_at(i)), out);
        }
      };
      // Raised cells go by runs along a row, from each run's first cell: the footprints over a
      // run's cells cover, in each mask row, one span (the run widened by the mask run), so a
      // cell is visited once per mask row instead of once per raised cell under it.
      int last = oc.x;  // last column of the run (the cell alone when lowered)
      if (pass == kRaised) {
        if (oc.x > 0 && stack.kind(o - 1) == kRaised) continue;  // not the first of its run
        while (last + 1 < w && stack.kind(o + static_cast<std::uint32_t>(last + 1 - oc.x)) == kRaised) ++last;
      }
      for (const MaskRun& r : mask_.runs) {
        const int y = oc.y - r.dy;
        if (y < 0 || y >= h) continue;
        const int lo = std::max(oc.x - r.hi, 0);
        const int hi = std::min(last - r.lo, w - 1);
        for (int x = lo; x <= hi; ++x) visit(x, y);
      }
      for (int x = oc.x; x <= last; ++x) visit(x, oc.y);
    }
  }
  // Clear the "checked" marks: the same cells again (a write per cell, no test).
  for (std::uint32_t o : cells) {
    if (stack.kind(o) != kLowered) continue;
    const Cell oc = map.cell_of_index(o);
    for (const MaskRun& r : mask_.runs) {
      const int y = oc.y - r.dy;
      if (y < 0 || y >= h) continue;
      const int lo = std::max(oc.x - r.hi, 0);
      const int hi = std::min(oc.x - r.lo, w - 1);
      for (int x = lo; x <= hi; ++x)
        stack.clear_checked(static_cast<std::uint32_t>(y) * static_cast<std::uint32_t>(w) + static_cast<std::uint32_t>(x));
    }
    stack.clear_checked(o);
  }
  if (Store::kClasses && out) {
    // Drop cells that flipped back, and clear the report marks.
    std::size_t keep = first;
    for (std::size_t k = first; k < out->size(); ++k) {
      const ClassChange ch = (*out)[k];
      stack.clear_reported(map.index(grid_.cell(ch.index)));
      if (grid_.cls[ch.index] != ch.before) (*out)[keep++] = ch;
    }
    out->resize(keep);
  }
}

}  // namespace robuter::plan
