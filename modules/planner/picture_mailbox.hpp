// SPDX-License-Identifier: GPL-3.0-or-later
// One-slot hand-off of plan snapshots from the planner (kernel thread) to the picture writer.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>

#include "modules/planner/lib/plan_snapshot.hpp"

namespace robuter::planner {

// The planner fills the slot in the activation that planned (no allocation, no lock, no
// waiting); the writer (another thread, or a test between ticks) draws it and frees it. If the
// writer still holds the previous picture, the new one is dropped and counted: the kernel never
// waits for a file.
class PictureMailbox {
 public:
  // Why: the allocation point (start-up): the snapshot sized for the planner's map.
  void reserve(const plan::Planner& planner, std::size_t max_path) { snap_.reserve(planner, max_path); }
  // Why: kernel side; the slot to fill, or null when it is taken (the picture is dropped).
  plan::PlanSnapshot* try_fill() {
    int expected = kFree;
    if (state_.compare_exchange_strong(expected, kFilling, std::memory_order_acquire)) return &snap_;
    dropped_.fetch_add(1, std::memory_order_relaxed);
    return nullptr;
  }
  // Why: kernel side; the slot filled by try_fill() is ready for the writer.
  void publish() {
    published_.fetch_add(1, std::memory_order_relaxed);
    state_.store(kReady, std::memory_order_release);
  }
  // Why: writer side; the snapshot to draw, or null when none is waiting.
  const plan::PlanSnapshot* take() {
    int expected = kReady;
    if (state_.compare_exchange_strong(expected, kDrawing, std::memory_order_acquire)) return &snap_;
    return nullptr;
  }
  // Why: writer side; done with the snapshot taken.
  void release() { state_.store(kFree, std::memory_order_release); }
  std::uint32_t published() const { return published_.load(std::memory_order_relaxed); }
  std::uint32_t dropped() const { return dropped_.load(std::memory_order_relaxed); }

 private:
  static constexpr int kFree = 0, kFilling = 1, kReady = 2, kDrawing = 3;
  plan::PlanSnapshot snap_;                   // the one slot
  std::atomic<int> state_{kFree};             // who holds the slot
  std::atomic<std::uint32_t> published_{0};   // snapshots handed over, count
  std::atomic<std::uint32_t> dropped_{0};     // plans without a picture (slot busy), count
};

}  // namespace robuter::planner
