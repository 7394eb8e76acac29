// SPDX-License-Identifier: GPL-3.0-or-later
// One-slot hand-off of a place's grid from the planner (kernel thread) to the place grid writer.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>

#include "modules/places/place_grid.hpp"

namespace robuter::places {

// The planner cuts a place's grid into the slot in the activation its scan ended (no allocation,
// no lock, no waiting); the writer (another thread, or a test between ticks) saves it and frees
// the slot. If the writer still holds the previous grid, the new one is dropped and counted.
class PlaceGridMailbox {
 public:
  // Why: the allocation point (start-up): room for the largest place's box on cells of
  // `resolution` (m), wherever the moving map's cells fall (a cell more each way).
  void reserve(const PlaceGraph& graph, double resolution) {
    plan::MapGeometry cells;
    cells.resolution = resolution;
    std::size_t most = 0;
    for (std::size_t k = 0; k < graph.places().size(); ++k) {
      const PlaceBox b = place_box(graph, k, cells);
      most = std::max(most, static_cast<std::size_t>(b.width + 1) * static_cast<std::size_t>(b.height + 1));
    }
    slot_.grid.cells.reserve(most);
    slot_.grid.place.reserve(64);
  }
  // One grid in the slot.
  struct Slot {
    std::size_t place = 0;  // the place's index in the graph
    std::uint64_t tick = 0; // the tick its scan ended
    PlaceGrid grid;         // its cells (grid.place is set by the writer)
  };
  // Why: kernel side; the slot to fill, or null when it is taken (the grid is dropped).
  Slot* try_fill() {
    int expected = kFree;
    if (state_.compare_exchange_strong(expected, kFilling, std::memory_order_acquire)) return &slot_;
    dropped_.fetch_add(1, std::memory_order_relaxed);
    return nullptr;
  }
  // Why: kernel side; the slot filled by try_fill() is ready for the writer (or given back
  // unfilled: `filled` false).
  void publish(bool filled = true) {
    if (!filled) {
      state_.store(kFree, std::memory_order_release);
      return;
    }
    published_.fetch_add(1, std::memory_order_relaxed);
    state_.store(kReady, std::memory_order_release);
  }
  // Why: writer side; the grid to save, or null when none is waiting.
  Slot* take() {
    int expected = kReady;
    if (state_.compare_exchange_strong(expected, kWriting, std::memory_order_acquire)) return &slot_;
    return nullptr;
  }
  // Why: writer side; done with the grid taken.
  void release() { state_.store(kFree, std::memory_order_release); }
  std::uint32_t published() const { return published_.load(std::memory_order_relaxed); }
  std::uint32_t dropped() const { return dropped_.load(std::memory_order_relaxed); }

 private:
  static constexpr int kFree = 0, kFilling = 1, kReady = 2, kWriting = 3;
  Slot slot_;                                 // the one slot
  std::atomic<int> state_{kFree};             // who holds the slot
  std::atomic<std::uint32_t> published_{0};   // grids handed over, count
  std::atomic<std::uint32_t> dropped_{0};     // grids not saved (slot busy), count
};

}  // namespace robuter::places
