// SPDX-License-Identifier: GPL-3.0-or-later
// How likely one sonar range is from a given pose, on the distance field of the robot's map.
#pragma once

#include <array>

#include <Eigen/Core>

#include "modules/localise/lib/distance_field.hpp"

namespace robuter::loc {

// The sonar model's constants (docs/LOCALISATION.md, "The sonar model").
struct SonarModelParams {
  double half_angle = 0.218;     // beam cone half-angle, rad (the ring's 12.5°)
  double max_range = 4.9;        // readings at or past this carry no echo, m
  double min_range = 0.15;       // blanking: readings nearer than this are not ranges, m
  double sigma_hit = 0.08;       // spread of an echo about the nearest mapped surface, m
  double z_hit = 0.75;           // weight of "the echo came off the map's surface"
  double z_rand = 0.25;          // weight of anything else (cross-talk, people, unmapped things)
  double through_weight = 0.35;  // factor when the beam's axis crosses a mapped wall short of the range
  int arc_samples = 5;           // points across the cone at the range (odd: one on the axis)
  // The echo the map promises (promises_echo): the silence and the nearer wall as evidence.
  double echo_incidence = 0.524; // a ray meets a mapped wall within this of its normal: it echoes
                                 // (rad, 30°: the simulator's ring loses echoes past 40°, and the
                                 // wall's normal here is the distance field's gradient, rougher)
  double arc_incidence = 0.873;  // an echo comes off a mapped wall the beam meets within this of
                                 // its normal (rad, 50°: the ring's 40° and the gradient's roughness)
  double miss_weight = 0.2;      // factor of a silent sensor (no echo) where the map promises one
  double miss_margin = 0.3;      // nearer than max_range by at least this, m
  double near_margin = 0.3;      // an echo the map promises this much nearer than the range: the
                                 // reading came through a wall (times through_weight), m
  int cone_rays = 3;             // rays traced across the cone (odd: one on the axis)
};

// One range reading in the robot's frame.
struct SonarReading {
  Eigen::Vector2d mount = Eigen::Vector2d::Zero();  // transducer ahead of / left of the axle midpoint, m
  double direction = 0.0;                           // beam axis, rad, counter-clockwise from forward
  double range = 0.0;                               // measured range, m (a silence: the firing's reach)
  bool silence = false;                             // no echo heard within `range` (the firing's reach)
};

// True when the reading says where a surface is (an echo inside the model's range). A silence
// says something only where the map promises an echo (silence_likelihood).
bool informative(const SonarReading& reading, const SonarModelParams& params);

// True when the reading is a silence the model can use: the sensor fired and heard no echo
// within its reach (`range`, past the blanking distance).
bool silent(const SonarReading& reading, const SonarModelParams& params);

// The directions across the cone the arc is read at, relative to the axis (cos, sin), worked
// out once from the params: no trigonometry per particle.
struct ArcTable {
  static constexpr int kMax = 9;              // most points across the cone
  std::array<Eigen::Vector2d, kMax> offsets;  // (cos, sin) of each point's angle off the axis
  int count = 0;                              // points in use
  double cos_incidence = 0.0;                 // cos of the most oblique incidence that echoes
                                              // (arc_incidence's or echo_incidence's)
};
ArcTable arc_table(const SonarModelParams& params);
// The same for the rays promises_echo() traces (cone_rays of them).
ArcTable cone_table(const SonarModelParams& params);

// Whether the map promises an echo nearer than `within` (m) to an ideal sonar at `origin`
// looking along the unit vector `axis`: one of the cone's rays, traced on the distance field,
// meets a wall's face (not its end) within echo_incidence of its normal (the field's gradient
// there) before `within` — and no wall nearer than min_range blinds the sensor first.
bool promises_echo(const DistanceField& field, const Eigen::Vector2d& origin, const Eigen::Vector2d& axis,
                   double within, const SonarModelParams& params, const ArcTable& cone);

// The likelihood of an informative reading for a sensor at `origin` looking along the unit
// vector `axis` (world frame), up to a constant factor shared by every pose: a mixture of an
// echo off the map (the nearest mapped surface the beam meets within arc_incidence of its normal,
// on the arc of radius `range` across the cone, Gaussian) and a uniform rest.
double arc_likelihood(const DistanceField& field, const Eigen::Vector2d& origin, const Eigen::Vector2d& axis,
                      double range, const SonarModelParams& params, const ArcTable& arc);

// How near the map must promise an echo for it to tell against a reading (promises_echo's
// `within`, m): a silence within `reach`, miss_margin inside it; an echo at `range`, near_margin
// short of it.
double silence_within(double reach, const SonarModelParams& params);
double echo_within(double range, const SonarModelParams& params);

// The factor an echo the map promises (nearer than echo_within() or silence_within()) puts on a
// reading: miss_weight on a silence, through_weight on an echo; 1 where none is promised. The one
// place this rule is made (sonar_likelihood(), silence_likelihood() and the filter use it).
double promise_factor(bool silence, bool promised, const SonarModelParams& params);

// The whole likelihood of an echo at `range`: arc_likelihood() times `through_weight` when the
// map promises an echo nearer than echo_within(range) (the beam would have echoed there).
double sonar_likelihood(const DistanceField& field, const Eigen::Vector2d& origin, const Eigen::Vector2d& axis,
                        double range, const SonarModelParams& params, const ArcTable& arc, const ArcTable& cone);
// The likelihood of a silence within `reach` (m): miss_weight when the map promises an echo
// nearer than silence_within(reach), else 1.
double silence_likelihood(const DistanceField& field, const Eigen::Vector2d& origin, const Eigen::Vector2d& axis,
                          double reach, const SonarModelParams& params, const ArcTable& cone);

}  // namespace robuter::loc
