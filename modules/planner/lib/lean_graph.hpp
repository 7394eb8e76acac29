// SPDX-License-Identifier: GPL-3.0-or-later
// The lean (cell, move slot) graph of one heading search, and its turn rule in one place.
#pragma once

#include <cstdint>

#include "modules/planner/lib/pass_grid.hpp"

namespace robuter::plan {

// The lean search's graph as HeadingSearch derives it for one search (arrays per slice or per
// move slot, cells in a PassGrid's bordered indexing); read by the search and by EnclosureTest.
struct LeanGraph {
  const std::uint8_t* const* cls_of = nullptr;  // per slice: its cell classes
  int slices = 0;                               // slices over the full turn
  int stride = 0;                               // stored cells per row
  int rows = 0;                                 // stored rows
  const int* move_slice = nullptr;              // per move slot: its slice
  int slots = 0;                                // move slots
  const int* slot_of = nullptr;                 // per slice: its move slot, or -1
  const std::uint8_t* allowed = nullptr;        // per slice: allowed move bits
  const std::uint32_t* turn_bits = nullptr;     // grown-body bits per stored cell (set = no room), or null
  int turn_words = 1;                           // uint32 words of turn_bits per cell
  std::uint32_t start = 0;                      // stored index of the start cell
  int start_slice = 0;                          // the robot's slice there
  std::uint32_t goal = 0;                       // stored index of the goal cell
};

// Why: the turn rule: can the robot turn in place at `cell` from slice `from` by `steps` slice
// steps in direction `dir` (+1 up, -1 down)? Each step j -> j' needs room at j and j' — the
// grown body's bits when `grown` (g.turn_bits must then be set), else the body's own classes —
// and the body itself clear at j' (the full graph's rule, step by step). The search asks the
// grown body everywhere but at the start cell, where the robot already stands.
inline bool arc_free(const LeanGraph& g, bool grown, std::uint32_t cell, int from, int steps, int dir) {
  const std::uint32_t* wb = grown ? g.turn_bits + cell * static_cast<std::uint32_t>(g.turn_words) : nullptr;
  auto no_room = [&](int j) {
    return grown ? ((wb[j >> 5] >> (j & 31)) & 1u) != 0 : g.cls_of[j][cell] == kBlocked;
  };
  if (no_room(from)) return false;
  int j = from;
  for (int q = 0; q < steps; ++q) {
    j = (j + dir + g.slices) % g.slices;
    if (no_room(j) || g.cls_of[j][cell] == kBlocked) return false;
  }
  return true;
}

// Why: from a slice that allows no grid move, the nearest move slice in direction `dir`; its
// slice index, and the slice steps to it in `steps` (the graph must have a move slot).
inline int next_move_slice(const LeanGraph& g, int from, int dir, int& steps) {
  int j = from;
  steps = 0;
  do j = (j + dir + g.slices) % g.slices, ++steps;
  while (g.slot_of[j] < 0);
  return j;
}

}  // namespace robuter::plan
