// SPDX-License-Identifier: GPL-3.0-or-later
// The arc likelihood field of one sonar range (sonar_likelihood.hpp).
#include "modules/localise/lib/sonar_likelihood.hpp"

#include <algorithm>
#include <cmath>

namespace robuter::loc {

bool informative(const SonarReading& reading, const SonarModelParams& params) {
  return reading.range >= params.min_range && reading.range < params.max_range;
}

ArcTable arc_table(const SonarModelParams& params) {
  ArcTable t;
  t.count = std::clamp(params.arc_samples, 1, ArcTable::kMax);
  for (int i = 0; i < t.count; ++i) {
    const double a = t.count == 1 ? 0.0 : -params.half_angle + 2.0 * params.half_angle * i / (t.count - 1);
    t.offsets[static_cast<std::size_t>(i)] = Eigen::Vector2d(std::cos(a), std::sin(a));
  }
  return t;
}

double sonar_likelihood(const DistanceField& field, const Eigen::Vector2d& origin, const Eigen::Vector2d& axis,
                        double range, const SonarModelParams& params, const ArcTable& arc) {
  // The echo: the nearest reflector may be anywhere across the cone at that range.
  double nearest = field.max_distance();
  for (int i = 0; i < arc.count; ++i) {
    const auto& o = arc.offsets[static_cast<std::size_t>(i)];
    const Eigen::Vector2d dir(axis.x() * o.x() - axis.y() * o.y(), axis.x() * o.y() + axis.y() * o.x());
    nearest = std::min(nearest, field.at(origin + range * dir));
  }
  const double hit = std::exp(-0.5 * nearest * nearest / (params.sigma_hit * params.sigma_hit));
  double p = params.z_hit * hit + params.z_rand;
  // Negative evidence along the axis: a wall crossed short of the range would have echoed.
  const double step = 2.0 * field.geometry().resolution;
  const double stop = range - 3.0 * params.sigma_hit;
  for (double r = params.min_range; r < stop; r += step) {
    if (field.at(origin + r * axis) < 0.5 * step) {  // a wall crossing the axis is this near a sample
      p *= params.through_weight;
      break;
    }
  }
  return p;
}

}  // namespace robuter::loc
