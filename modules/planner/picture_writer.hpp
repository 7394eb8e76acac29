// SPDX-License-Identifier: GPL-3.0-or-later
// The firmware's planner pictures: a thread (outside the kernel) that writes each plan's PNG.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>

#include "kernel/drain_writer.hpp"
#include "modules/planner/picture_mailbox.hpp"

namespace robuter::planner {

// Draws every snapshot the planner hands over into `dir`/plan-gGGG-NNN.png (goal sequence,
// plan number: 001 is the first plan for the goal, then the replans). PNG writing is blocking
// I/O, so it runs on its own thread at normal priority (robuterd --planner-pictures), or between
// ticks when a test steps a virtual clock (drain()).
class PictureWriter final : public DrainWriter<PictureMailbox> {
 public:
  // Where the planner's (odometry) frame lies in the world now (m, rad), asked before each
  // picture; empty when unknown (the real robot): the pictures are then in the odometry frame.
  using FrameSource = std::function<std::optional<plan::Pose2>()>;
  PictureWriter(std::string dir, PictureMailbox& box, FrameSource map_in_world = {})
      : DrainWriter("planner picture", std::move(dir), box), map_in_world_(std::move(map_in_world)) {}
  ~PictureWriter() override { stop(); }

 private:
  // Draws the snapshot into its PNG.
  std::optional<std::string> write(const plan::PlanSnapshot& snap) override;

  FrameSource map_in_world_;  // the odometry frame in the world, if known
};

}  // namespace robuter::planner
