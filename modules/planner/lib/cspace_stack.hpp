// SPDX-License-Identifier: GPL-3.0-or-later
// What every C-space layer shares: the occupancy it was built from, as a summed-area table.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "modules/planner/lib/footprint.hpp"
#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/planner/lib/pass_grid.hpp"

namespace robuter::plan {

// Why: the class a cell takes with no footprint over it (one rule for the stack's copies and
// the layers' writes): kBlocked on an obstacle, else kFree or kUnknown as the map says.
inline std::uint8_t own_class(CellState s) {
  return s == CellState::Occupied ? kBlocked : s == CellState::Unknown ? kUnknown : kFree;
}

// How a logged map cell changed for the layers in one sync (CSpaceStack::kind()).
enum CellChange : std::uint8_t {
  kNoChange = 0,    // not logged, or logged with nothing the layers see changed
  kRaised = 1,      // became occupied
  kLowered = 2,     // was occupied, no longer is
  kRelabelled = 3,  // free <-> unknown, occupancy unchanged
};

// The part of the C-space that is the same for every layer, kept once: which map cells are
// occupied (a summed-area table of 16-bit counts taken modulo 2^16, exact for any rectangle of
// fewer than 65,536 cells), and one byte per cell of marks for the layers' updates (the change
// kind of the current sync, and a layer's "already reported" and "already re-tested"). The layers hold only their
// classes; a layer asks here whether any occupied cell lies under its mask at a cell.
// For full builds the occupancy is also kept as row bitsets with a sparse table of spans (bit x
// of level k: an occupied cell in columns [x, x + 2^k)), so that a mask run's dilation of a row
// is two shifted ORs of 64-bit words (dilate_row), and each cell's class without any footprint
// (free, unknown or blocked by its own obstacle) is kept for the layers to copy.
class CSpaceStack {
 public:
  // Why: size for the map and take its occupancy (set_map; allocates).
  void reset(const OccupancyMap& map);

  // Why: fold the map's logged changes before the layers update: each cell's kind is set, and
  // the table is rebuilt when the occupancy changed. end_sync() must follow the layers.
  // Returns the cells of kind kLowered (the layers' costly kind: Planner::sync()).
  std::uint32_t begin_sync(const OccupancyMap& map, std::span<const std::uint32_t> cells);
  // Why: clear the kinds set by begin_sync.
  void end_sync(std::span<const std::uint32_t> cells);

  int width() const { return w_; }
  int height() const { return h_; }
  // Why: the kind of a map cell's change in the current sync.
  CellChange kind(std::uint32_t map_index) const {
    return static_cast<CellChange>(marks_[map_index] & kKindBits);
  }
  // Why: occupied cells in columns [x0, x1] of rows [y0, y1], clipped to the map (wraps past
  // 65,535 cells: callers ask about rectangles smaller than that, or only compare with 0).
  std::uint16_t count(int x0, int y0, int x1, int y1) const {
    x0 = x0 < 0 ? 0 : x0;
    y0 = y0 < 0 ? 0 : y0;
    x1 = x1 >= w_ ? w_ - 1 : x1;
    y1 = y1 >= h_ ? h_ - 1 : y1;
    if (x0 > x1 || y0 > y1) return 0;
    const std::uint16_t* a = sat_.data() + static_cast<std::size_t>(y0) * stride_;
    const std::uint16_t* b = sat_.data() + static_cast<std::size_t>(y1 + 1) * stride_;
    return static_cast<std::uint16_t>(b[x1 + 1] - b[x0] - a[x1 + 1] + a[x0]);
  }
  // Why: one row's run, the layers' inner test.
  bool any_in_row(int y, int x0, int x1) const { return count(x0, y, x1, y) != 0; }
  bool occupied(int x, int y) const { return any_in_row(y, x, x); }

  // Why: a layer's full build (CSpaceLayer::fill): ORs into `out` (row_words() words, zeroed by
  // the caller) bit x for each cell (x, y) whose footprint `runs` meets an occupied cell. Bits
  // past the map's width stay clear.
  void dilate_row(std::span<const MaskRun> runs, int y, std::uint64_t* out) const;
  int row_words() const { return wpr_; }
  // Why: the class of each cell of row y with no footprint (what a layer copies where its
  // footprint meets nothing): kBlocked on an obstacle, else kFree or kUnknown.
  const std::uint8_t* base_row(int y) const { return base_.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(w_); }
  // Why: a build's row of bits without allocating (one row; not reentrant).
  std::uint64_t* scratch() const { return scratch_.data(); }
  // Why: a layer update's window of bits around new obstacles (CSpaceLayer): `words` words
  // without allocating, or null when the window is larger than the stack holds (kWindowWords;
  // not reentrant).
  std::uint64_t* window(std::size_t words) const {
    if (words > window_.size()) return nullptr;
    ++windows_;
    return window_.data();
  }
  // Why: how many layer updates went by a window since reset() (tests see both paths taken).
  std::size_t windows() const { return windows_; }
  static constexpr std::size_t kWindowWords = 4096;  // 32 kB: e.g. 512 rows of 8 words (512 cells)

  // Why: a layer's update marks a cell reported once (bit kReported of the per-cell byte).
  bool mark_reported(std::uint32_t map_index) { return set_mark(map_index, kReported); }
  void clear_reported(std::uint32_t map_index) { clear_mark(map_index, kReported); }

  // Why: a layer's update re-tests a cell once (bit kChecked of the per-cell byte).
  bool mark_checked(std::uint32_t map_index) { return set_mark(map_index, kChecked); }
  void clear_checked(std::uint32_t map_index) { clear_mark(map_index, kChecked); }

 private:
  // Sets `bit` of a cell's byte; false when it was set already.
  bool set_mark(std::uint32_t map_index, std::uint8_t bit) {
    if (marks_[map_index] & bit) return false;
    marks_[map_index] = static_cast<std::uint8_t>(marks_[map_index] | bit);
    return true;
  }
  // Clears `bit` of a cell's byte.
  void clear_mark(std::uint32_t map_index, std::uint8_t bit) {
    marks_[map_index] = static_cast<std::uint8_t>(marks_[map_index] & ~bit);
  }

  static constexpr std::uint8_t kKindBits = 3;
  static constexpr std::uint8_t kReported = 4;
  static constexpr std::uint8_t kChecked = 8;
  void rebuild(const OccupancyMap& map);
  void rebuild_table(const OccupancyMap& map, int y0);
  void rebuild_row(const OccupancyMap& map, int y);

  int w_ = 0;                        // cells
  int h_ = 0;                        // cells
  std::size_t stride_ = 1;           // table entries per row (w_ + 1)
  std::vector<std::uint16_t> sat_;   // (h_ + 1) x (w_ + 1): occupied cells in [0, x) x [0, y), mod 2^16
  std::vector<std::uint8_t> marks_;  // per map cell: CellChange | kReported | kChecked
  static constexpr int kLevels = 7;  // span levels: runs up to 2^(kLevels-1) = 64 cells in two ORs
  int wpr_ = 1;                      // 64-bit words per bitset row: (w_ + 63) / 64
  std::vector<std::uint64_t> spans_; // kLevels x h_ x wpr_: level k, row y, bit x = occupied in [x, x + 2^k)
  std::vector<std::uint8_t> row_any_;  // per row: 1 when it holds an occupied cell
  std::vector<std::uint8_t> row_dirty_;  // per row: holds a cell of the current begin_sync (cleared by it)
  std::vector<std::uint8_t> base_;   // per map cell: CellClass with no footprint
  mutable std::vector<std::uint64_t> scratch_;  // wpr_ words for a build's row
  mutable std::vector<std::uint64_t> window_;   // kWindowWords words for an update's window
  mutable std::size_t windows_ = 0;             // window() calls that returned the window
};

}  // namespace robuter::plan
