// SPDX-License-Identifier: GPL-3.0-or-later
// The place grid thread: name the grid taken from the mailbox after its place, save it as text.
#include "modules/places/place_grid_writer.hpp"

namespace robuter::places {

std::optional<std::string> PlaceGridWriter::write(PlaceGridSlot& slot) {
  slot.grid.place = graph_.places().at(slot.place).name;
  const auto st = save_place_grid(slot.grid, place_grid_path(dir_, slot.grid.place));
  if (!st) return st.error().text();
  return std::nullopt;
}

}  // namespace robuter::places
