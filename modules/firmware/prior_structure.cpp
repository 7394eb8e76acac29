// SPDX-License-Identifier: GPL-3.0-or-later
// Known structure from the a-priori map: a point test on its occupied cells, in the map frame.
#include "modules/firmware/prior_structure.hpp"

#include <algorithm>
#include <numbers>

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
  const Posture& p = posture_.peek();
  to_map_ = localise::map_from_odometry(l, p.odometry_seq);
  robot_ = Eigen::Vector2d(p.x * 1e-4, p.y * 1e-4);
  const bool localised = localise::corrects(l, p.odometry_seq);
  slack_ = localised ? 0.5 * map_.resolution() + 2.0 * l.major_mm * 1e-3 : 0.0;
  turn_slack_ = localised ? 2.0 * l.sigma_theta * 1e-2 * std::numbers::pi / 180.0 : 0.0;
}

bool PriorMapStructure::occupied(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d m = to_map_ * p;
  const double q = 0.25 * map_.resolution();
  for (const Eigen::Vector2d& d : {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(q, 0.0), Eigen::Vector2d(-q, 0.0),
                                   Eigen::Vector2d(0.0, q), Eigen::Vector2d(0.0, -q)}) {
    const plan::Cell c = map_.cell_of({m.x() + d.x(), m.y() + d.y()});
    if (map_.contains(c) && map_.state(c) == plan::CellState::Occupied) return true;
  }
  if (slack_ <= 0.0) return false;
  // A heading error moves a wall at distance d from the robot by d times it.
  return field_.at(m) <= std::min(kMaxSlack, slack_ + turn_slack_ * (p - robot_).norm());
}

}  // namespace robuter
