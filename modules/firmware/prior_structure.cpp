// SPDX-License-Identifier: GPL-3.0-or-later
// Known structure from the a-priori map: a point test on its occupied cells.
#include "modules/firmware/prior_structure.hpp"

namespace robuter {

bool PriorMapStructure::occupied(const Eigen::Vector2d& p) const {
  const double q = 0.25 * map_.resolution();
  for (const Eigen::Vector2d& d : {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(q, 0.0), Eigen::Vector2d(-q, 0.0),
                                   Eigen::Vector2d(0.0, q), Eigen::Vector2d(0.0, -q)}) {
    const plan::Cell c = map_.cell_of({p.x() + d.x(), p.y() + d.y()});
    if (map_.contains(c) && map_.state(c) == plan::CellState::Occupied) return true;
  }
  return false;
}

}  // namespace robuter
