// SPDX-License-Identifier: GPL-3.0-or-later
// The place grid thread: take a grid from the mailbox, save it as text, free the slot.
#include "modules/places/place_grid_writer.hpp"

#include <chrono>
#include <cstdio>

namespace robuter::places {

bool PlaceGridWriter::drain() {
  PlaceGridMailbox::Slot* slot = box_.take();
  if (slot == nullptr) return false;
  slot->grid.place = graph_.places().at(slot->place).name;
  const auto st = save_place_grid(slot->grid, place_grid_path(dir_, slot->grid.place));
  box_.release();
  if (!st) {
    // Not the kernel's thread: a message on stderr costs the robot nothing.
    if (failed_.fetch_add(1) == 0) std::fprintf(stderr, "robuterd: place grid: %s\n", st.error().text().c_str());
    return false;
  }
  written_.fetch_add(1);
  return true;
}

void PlaceGridWriter::start() {
  if (thread_.joinable()) return;
  stop_ = false;
  thread_ = std::thread([this] {
    while (!stop_.load()) {
      if (!drain()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  });
}

void PlaceGridWriter::stop() {
  if (thread_.joinable()) {
    stop_ = true;
    thread_.join();
  }
  drain();
}

}  // namespace robuter::places
