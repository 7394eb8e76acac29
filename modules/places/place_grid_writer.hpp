// SPDX-License-Identifier: GPL-3.0-or-later
// The firmware's place grids: a thread (outside the kernel) that saves each place's grid as text.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <utility>

#include "kernel/handoff.hpp"
#include "modules/places/place_grid_mailbox.hpp"

namespace robuter::places {

// Saves every grid the planner hands over as `dir`/<place>.txt (the place's latest grid: seed
// 003's drawsec() after each node's scan). File writing is blocking I/O, so it runs on its own
// thread (robuterd), or between ticks when a test steps a virtual clock (drain()).
class PlaceGridWriter {
 public:
  PlaceGridWriter(std::string dir, const PlaceGraph& graph, PlaceGridMailbox& box)
      : dir_(std::move(dir)), graph_(graph), box_(box) {}
  ~PlaceGridWriter() { stop(); }
  PlaceGridWriter(const PlaceGridWriter&) = delete;
  PlaceGridWriter& operator=(const PlaceGridWriter&) = delete;

  // Why: saves the waiting grid, if any; true if a file was written.
  bool drain();
  // Why: robuterd: drain every 10 ms on a thread of its own until stop().
  void start() { thread_.start([this] { return drain(); }); }
  // Why: joins the thread, then saves what is still waiting.
  void stop() {
    thread_.stop();
    drain();
  }
  bool running() const { return thread_.running(); }
  std::uint32_t written() const { return written_.load(); }
  std::uint32_t failed() const { return failed_.load(); }
  std::uint32_t dropped() const { return box_.dropped(); }
  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;                        // folder of the grids
  const PlaceGraph& graph_;                // the places' names
  PlaceGridMailbox& box_;                  // where the planner leaves grids
  DrainThread thread_;                     // the writer thread (robuterd), or none (tests)
  std::atomic<std::uint32_t> written_{0};  // grids saved, count
  std::atomic<std::uint32_t> failed_{0};   // grids that could not be saved, count
};

}  // namespace robuter::places
