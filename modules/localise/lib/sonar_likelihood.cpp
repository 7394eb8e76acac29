// SPDX-License-Identifier: GPL-3.0-or-later
// The arc likelihood field of one sonar range (sonar_likelihood.hpp).
#include "modules/localise/lib/sonar_likelihood.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace robuter::loc {

bool informative(const SonarReading& reading, const SonarModelParams& params) {
  return !reading.silence && reading.range >= params.min_range && reading.range < params.max_range;
}

bool silent(const SonarReading& reading, const SonarModelParams& params) {
  return reading.silence && reading.range > params.min_range;
}

namespace {
ArcTable table(const SonarModelParams& params, int points, double incidence) {
  ArcTable t;
  t.cos_incidence = std::cos(incidence);
  t.count = std::clamp(points, 1, ArcTable::kMax);
  for (int i = 0; i < t.count; ++i) {
    const double a = t.count == 1 ? 0.0 : -params.half_angle + 2.0 * params.half_angle * i / (t.count - 1);
    t.offsets[static_cast<std::size_t>(i)] = Eigen::Vector2d(std::cos(a), std::sin(a));
  }
  return t;
}
}  // namespace

ArcTable arc_table(const SonarModelParams& params) { return table(params, params.arc_samples, params.arc_incidence); }
ArcTable cone_table(const SonarModelParams& params) { return table(params, params.cone_rays, params.echo_incidence); }

bool promises_echo(const DistanceField& field, const Eigen::Vector2d& origin, const Eigen::Vector2d& axis,
                   double within, const SonarModelParams& params, const ArcTable& cone) {
  constexpr int kMaxSteps = 32;   // sphere-tracing steps per ray
  const double res = field.geometry().resolution;
  const double hit = 0.75 * res;  // a cell centre this near an occupied one's: the ray met the wall
  const double cos_echo = cone.cos_incidence;
  const double limit = std::min(within, params.max_range);
  // No wall within min_range of the transducer: nothing can blind it, the first echo answers.
  const bool may_blind = field.at(origin) < params.min_range + res;
  bool found = false;
  for (int i = 0; i < cone.count; ++i) {
    const auto& o = cone.offsets[static_cast<std::size_t>(i)];
    const Eigen::Vector2d dir(axis.x() * o.x() - axis.y() * o.y(), axis.x() * o.y() + axis.y() * o.x());
    double r = 0.0;
    for (int k = 0; k < kMaxSteps && r < limit; ++k) {
      const Eigen::Vector2d p = origin + r * dir;
      const double d = field.at(p);
      if (d > 4.0 * res) {
        r += d - hit;
        continue;
      }
      // Near a wall: the ray meets it at the incidence the gradient gives (a ray along a wall
      // would step on for ever: it meets the wall at grazing, which returns nothing).
      Eigen::Vector2d g;
      if (!field.normal(p, g)) {
        r += std::max(d - hit, 0.5 * res);
        continue;
      }
      const double facing = -dir.dot(g);  // cos of the incidence
      if (facing >= 0.0 && facing < cos_echo) break;  // meets it at grazing: no echo along this ray
      if (d > hit || facing < 0.0) {                  // still short of it, or leaving it
        r += std::max(d - hit, 0.5 * res);
        continue;
      }
      if (r < params.min_range) return false;  // blinded
      // A face, not a wall's end: the wall goes on a cell either side along it.
      const Eigen::Vector2d t(-g.y(), g.x());
      if (field.at(p + res * t) <= hit || field.at(p - res * t) <= hit) {
        if (!may_blind) return true;
        found = true;  // unless another ray finds the sensor blinded
      }
      break;  // the ray ends at the first wall
    }
  }
  return found;
}

double silence_within(double reach, const SonarModelParams& params) {
  return std::min(reach, params.max_range) - params.miss_margin;
}
double echo_within(double range, const SonarModelParams& params) { return range - params.near_margin; }

double promise_factor(bool silence, bool promised, const SonarModelParams& params) {
  if (!promised) return 1.0;
  return silence ? params.miss_weight : params.through_weight;
}

double silence_likelihood(const DistanceField& field, const Eigen::Vector2d& origin, const Eigen::Vector2d& axis,
                          double reach, const SonarModelParams& params, const ArcTable& cone) {
  return promise_factor(true, promises_echo(field, origin, axis, silence_within(reach, params), params, cone), params);
}

double sonar_likelihood(const DistanceField& field, const Eigen::Vector2d& origin, const Eigen::Vector2d& axis,
                        double range, const SonarModelParams& params, const ArcTable& arc, const ArcTable& cone) {
  return arc_likelihood(field, origin, axis, range, params, arc) *
         promise_factor(false, promises_echo(field, origin, axis, echo_within(range, params), params, cone), params);
}

double arc_likelihood(const DistanceField& field, const Eigen::Vector2d& origin, const Eigen::Vector2d& axis,
                      double range, const SonarModelParams& params, const ArcTable& arc) {
  // The echo: the nearest reflector may be anywhere across the cone at that range, if the beam
  // meets it within arc_incidence of its normal (a wall met at grazing returns nothing).
  const double cos_echo = arc.cos_incidence;
  double nearest = field.max_distance();
  for (int i = 0; i < arc.count; ++i) {
    const auto& o = arc.offsets[static_cast<std::size_t>(i)];
    const Eigen::Vector2d dir(axis.x() * o.x() - axis.y() * o.y(), axis.x() * o.y() + axis.y() * o.x());
    const Eigen::Vector2d q = origin + range * dir;
    const double d = field.at(q);
    if (d >= nearest) continue;
    Eigen::Vector2d g;
    if (d < 3.0 * params.sigma_hit && field.normal(q, g) && std::abs(dir.dot(g)) < cos_echo) continue;  // met at grazing
    nearest = d;
  }
  const double hit = std::exp(-0.5 * nearest * nearest / (params.sigma_hit * params.sigma_hit));
  return params.z_hit * hit + params.z_rand;
}

}  // namespace robuter::loc
