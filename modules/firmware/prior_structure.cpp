// SPDX-License-Identifier: GPL-3.0-or-later
// Known structure from the a-priori map: a point test on its occupied cells, in the map frame.
#include "modules/firmware/prior_structure.hpp"

#include <algorithm>

#include "modules/localise/map_field.hpp"
#include "modules/localise/map_frame.hpp"

namespace robuter {

PriorMapStructure::PriorMapStructure(plan::OccupancyMap map, Reader<Localisation> localisation, Reader<Posture> posture)
    : map_(std::move(map)),
      field_(localise::distance_field(map_, kMaxSlack + map_.resolution())),
      localisation_(localisation),
      posture_(posture) {}

void PriorMapStructure::update() {
  const Localisation& l = localisation_.peek();
  const std::uint32_t seq = posture_.peek().odometry_seq;
  to_map_ = localise::map_from_odometry(l, seq);
  slack_ = localise::corrects(l, seq) ? std::min(kMaxSlack, 0.5 * map_.resolution() + 2.0 * l.major_mm * 1e-3) : 0.0;
}

bool PriorMapStructure::occupied(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d m = to_map_ * p;
  const double q = 0.25 * map_.resolution();
  for (const Eigen::Vector2d& d : {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(q, 0.0), Eigen::Vector2d(-q, 0.0),
                                   Eigen::Vector2d(0.0, q), Eigen::Vector2d(0.0, -q)}) {
    const plan::Cell c = map_.cell_of({m.x() + d.x(), m.y() + d.y()});
    if (map_.contains(c) && map_.state(c) == plan::CellState::Occupied) return true;
  }
  return slack_ > 0.0 && field_.at(m) <= slack_;
}

}  // namespace robuter
