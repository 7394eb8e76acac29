// SPDX-License-Identifier: GPL-3.0-or-later
// The firmware's planner pictures: a thread (outside the kernel) that writes each plan's PNG.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>

#include "kernel/handoff.hpp"
#include "modules/planner/picture_mailbox.hpp"

namespace robuter::planner {

// Draws every snapshot the planner hands over into `dir`/plan-gGGG-NNN.png (goal sequence,
// plan number: 001 is the first plan for the goal, then the replans). PNG writing is blocking
// I/O, so it runs on its own thread at normal priority (robuterd --planner-pictures), or between
// ticks when a test steps a virtual clock (drain()).
class PictureWriter {
 public:
  // Where the planner's (odometry) frame lies in the world now (m, rad), asked before each
  // picture; empty when unknown (the real robot): the pictures are then in the odometry frame.
  using FrameSource = std::function<std::optional<plan::Pose2>()>;
  PictureWriter(std::string dir, PictureMailbox& box, FrameSource map_in_world = {})
      : dir_(std::move(dir)), box_(box), map_in_world_(std::move(map_in_world)) {}
  ~PictureWriter() { stop(); }
  PictureWriter(const PictureWriter&) = delete;
  PictureWriter& operator=(const PictureWriter&) = delete;

  // Why: writes the waiting snapshot, if any; true if a picture was written.
  bool drain();
  // Why: robuterd: drain every 10 ms on a thread of its own until stop().
  void start() { thread_.start([this] { return drain(); }); }
  // Why: joins the thread, then writes what is still waiting.
  void stop() {
    thread_.stop();
    drain();
  }
  bool running() const { return thread_.running(); }
  std::uint32_t written() const { return written_.load(); }
  std::uint32_t failed() const { return failed_.load(); }
  // Why: plans whose picture was dropped because the writer was still drawing (each one logged).
  std::uint32_t dropped() const { return box_.dropped(); }
  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;                       // folder of the pictures
  PictureMailbox& box_;                   // where the planner leaves snapshots
  FrameSource map_in_world_;              // the odometry frame in the world, if known
  DrainThread thread_;                    // the writer thread (robuterd), or none (tests)
  std::atomic<std::uint32_t> written_{0}; // pictures written, count
  std::atomic<std::uint32_t> failed_{0};  // pictures that could not be written, count
};

}  // namespace robuter::planner
