// SPDX-License-Identifier: GPL-3.0-or-later
// One-slot hand-off of plan snapshots from the planner (kernel thread) to the picture writer.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kernel/handoff.hpp"
#include "modules/planner/lib/plan_snapshot.hpp"

namespace robuter::planner {

// The planner fills the slot in the activation that planned; the writer (another thread, or a
// test between ticks) draws it and frees it (OneSlot: never waited for, drops counted).
class PictureMailbox {
 public:
  // Why: the allocation point (start-up): the snapshot sized for the planner's map.
  void reserve(const plan::Planner& planner, std::size_t max_path) { slot_.value().reserve(planner, max_path); }
  // Why: kernel side; the slot to fill, or null when it is taken (the picture is dropped).
  plan::PlanSnapshot* try_fill() { return slot_.try_fill(); }
  // Why: kernel side; the slot filled by try_fill() is ready for the writer.
  void publish() { slot_.publish(); }
  // Why: writer side; the snapshot to draw, or null when none is waiting.
  const plan::PlanSnapshot* take() { return slot_.take(); }
  // Why: writer side; done with the snapshot taken.
  void release() { slot_.release(); }
  std::uint32_t published() const { return slot_.published(); }
  std::uint32_t dropped() const { return slot_.dropped(); }

 private:
  OneSlot<plan::PlanSnapshot> slot_;  // the one snapshot
};

}  // namespace robuter::planner
