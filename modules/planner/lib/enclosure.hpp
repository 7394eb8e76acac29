// SPDX-License-Identifier: GPL-3.0-or-later
// Is the robot shut in? A bit-parallel flood of the lean (cell, move slot) graph in a window.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "modules/planner/lib/slice_bits.hpp"

namespace robuter::plan {

// The lean search's graph as HeadingSearch holds it for one search (all arrays per slice or per
// move slot, cells in a PassGrid's bordered indexing).
struct LeanGraph {
  const std::uint8_t* const* cls_of = nullptr;  // per slice: its cell classes
  int slices = 0;                               // slices over the full turn
  int stride = 0;                               // stored cells per row
  int rows = 0;                                 // stored rows
  const int* move_slice = nullptr;              // per move slot: its slice
  int slots = 0;                                // move slots
  const int* slot_of = nullptr;                 // per slice: its move slot, or -1
  const std::uint8_t* allowed = nullptr;        // per slice: allowed move bits
  const SliceBits* turn_room = nullptr;         // grown-body bits (turning needs them clear), or null
  std::uint32_t start = 0;                      // stored index of the start cell
  int start_slice = 0;                          // the robot's slice there
  std::uint32_t goal = 0;                       // stored index of the goal cell
};

// Why: a search that ends "unreachable" has to exhaust the robot's whole component of the
// (cell, move slot) graph, one state at a time — ~17 k states when a new obstacle shuts the
// robot in a corner of a room. If that component fits in a window of 128 x 128 cells, a flood of
// the window's states as bits (two 64-bit words per row and move slot: straight runs in one sweep
// per direction, turns as ANDs between neighbouring slots) proves it in a few thousand word
// operations. Exact as a proof: the window's graph is the search's graph or a superset of it
// (turns are allowed where the grown body's bits are clear, which the search also requires),
// so "enclosed" — the flood from the start never reaches the window's outer ring nor the goal
// — means the search would end unreachable. Anything else is "open" (not known): search on.
// No allocation after reserve().
class EnclosureTest {
 public:
  static constexpr int kWords = 2;             // 64-bit words per window row
  static constexpr int kSize = 64 * kWords;    // cells per side of the window

  // Why: buffers for up to `slots` move slots (the only allocation).
  void reserve(int slots);

  // Why: flood the graph in the window whose stored corner is (x0, y0). True when the start's
  // component lies inside it, away from its outer ring, without the goal.
  bool enclosed(const LeanGraph& g, int x0, int y0);

  // Word operations of the last enclosed() call's flood (tests and figures).
  std::uint32_t last_sweeps() const { return sweeps_; }

 private:
  using Rows = std::array<std::uint64_t, static_cast<std::size_t>(kSize * kWords)>;  // row y: words [y * kWords, ...)
  std::vector<Rows> free_;  // per slot: bit x of row y set = the slot's slice is not blocked there
  std::vector<Rows> turn_;  // per slot s: bit set = turning between slot s and s + 1 is allowed
  std::vector<Rows> seen_;  // per slot: reached states
  std::uint32_t sweeps_ = 0;
};

}  // namespace robuter::plan
