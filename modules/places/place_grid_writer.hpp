// SPDX-License-Identifier: GPL-3.0-or-later
// The firmware's place grids: a thread (outside the kernel) that saves each place's grid as text.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "kernel/drain_writer.hpp"
#include "modules/places/place_grid_mailbox.hpp"

namespace robuter::places {

// Saves every grid the planner hands over as `dir`/<place>.txt (the place's latest grid: seed
// 003's drawsec() after each node's scan). File writing is blocking I/O, so it runs on its own
// thread (robuterd), or between ticks when a test steps a virtual clock (drain()).
class PlaceGridWriter final : public DrainWriter<PlaceGridMailbox> {
 public:
  PlaceGridWriter(std::string dir, const PlaceGraph& graph, PlaceGridMailbox& box)
      : DrainWriter("place grid", std::move(dir), box), graph_(graph) {}
  ~PlaceGridWriter() override { stop(); }

 private:
  // Names the grid after its place and saves it.
  std::optional<std::string> write(PlaceGridSlot& slot) override;

  const PlaceGraph& graph_;  // the places' names
};

}  // namespace robuter::places
