// SPDX-License-Identifier: GPL-3.0-or-later
// Is the robot shut in? A bit-parallel flood of the lean (cell, move slot) graph in a window.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "modules/planner/lib/lean_graph.hpp"

namespace robuter::plan {

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

 private:
  using Rows = std::array<std::uint64_t, static_cast<std::size_t>(kSize * kWords)>;  // row y: words [y * kWords, ...)
  // The window: stored corner (x0, y0); stored columns [xa, xb) and rows [ya, yb) on the map.
  struct Window {
    int x0, y0, xa, xb, ya, yb;
  };
  void pack_free(const LeanGraph& g, const Window& w);            // free_ from the move slices
  void pack_turns(const LeanGraph& g, const Window& w, int sx, int sy);  // turn_ between slots
  void seed(const LeanGraph& g, int sx, int sy);                  // seen_: the start's states
  bool flood(const LeanGraph& g, int gx, int gy);                 // seen_ to its closure: enclosed?

  std::vector<Rows> free_;  // per slot: bit x of row y set = the slot's slice is not blocked there
  std::vector<Rows> turn_;  // per slot s: bit set = turning between slot s and s + 1 is allowed
  std::vector<Rows> seen_;  // per slot: reached states
};

}  // namespace robuter::plan
