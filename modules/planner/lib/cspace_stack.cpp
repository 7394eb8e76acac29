// SPDX-License-Identifier: GPL-3.0-or-later
// The layers' shared occupancy table and per-cell marks.
#include "modules/planner/lib/cspace_stack.hpp"

#include <algorithm>

namespace robuter::plan {

void CSpaceStack::reset(const OccupancyMap& map) {
  w_ = map.width();
  h_ = map.height();
  stride_ = static_cast<std::size_t>(w_) + 1;
  sat_.assign(stride_ * (static_cast<std::size_t>(h_) + 1), 0);
  marks_.assign(map.cell_count(), 0);
  rebuild(map);
}

// Why: O(cells) additions, cheaper than any per-cell upkeep once a sync changed a few hundred.
void CSpaceStack::rebuild(const OccupancyMap& map) {
  for (int y = 0; y < h_; ++y) {
    const std::uint16_t* above = sat_.data() + static_cast<std::size_t>(y) * stride_;
    std::uint16_t* row = sat_.data() + static_cast<std::size_t>(y + 1) * stride_;
    std::uint16_t run = 0;  // occupied cells of this row left of x, mod 2^16
    const std::uint32_t base = static_cast<std::uint32_t>(y) * static_cast<std::uint32_t>(w_);
    for (int x = 0; x < w_; ++x) {
      run = static_cast<std::uint16_t>(run + (map.state_at(base + static_cast<std::uint32_t>(x)) == CellState::Occupied));
      row[x + 1] = static_cast<std::uint16_t>(above[x + 1] + run);
    }
  }
}

void CSpaceStack::begin_sync(const OccupancyMap& map, std::span<const std::uint32_t> cells) {
  bool moved = false;
  for (std::uint32_t o : cells) {
    const Cell c = map.cell_of_index(o);
    const bool occ = map.state_at(o) == CellState::Occupied;
    const bool was = occupied(c.x, c.y);
    const CellChange k = occ == was ? kRelabelled : occ ? kRaised : kLowered;
    marks_[o] = static_cast<std::uint8_t>((marks_[o] & ~kKindBits) | k);
    moved = moved || occ != was;
  }
  if (moved) rebuild(map);
}

void CSpaceStack::end_sync(std::span<const std::uint32_t> cells) {
  for (std::uint32_t o : cells) marks_[o] = static_cast<std::uint8_t>(marks_[o] & ~kKindBits);
}

}  // namespace robuter::plan
