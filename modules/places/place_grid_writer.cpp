// SPDX-License-Identifier: GPL-3.0-or-later
// The place grid thread: take a grid from the mailbox, save it as text, free the slot.
#include "modules/places/place_grid_writer.hpp"

#include <cstdio>

namespace robuter::places {

bool PlaceGridWriter::drain() {
  PlaceGridSlot* slot = box_.take();
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

}  // namespace robuter::places
