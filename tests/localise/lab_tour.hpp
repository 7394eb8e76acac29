// SPDX-License-Identifier: GPL-3.0-or-later
// A tour of a simulated world for the localisation tests: true poses, noisy odometry, the ring's ranges.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hal/sim/world.hpp"
#include "modules/localise/lib/distance_field.hpp"
#include "modules/localise/lib/particle_filter.hpp"

namespace robuter::loc::test {

// A world and its map as the filter gets it (every wall and box rastered at 5 cm).
struct Lab {
  sim::World world;     // what the simulated sonar sees
  DistanceField field;  // what the filter is given
};
Lab load_lab(const std::string& file);

// How the tour is driven and measured.
struct TourSpec {
  std::vector<Eigen::Vector2d> waypoints;  // visited in order, the last back to the first, m
  Pose start = Pose::Zero();               // true (and odometry) start pose
  int laps = 1;                            // times round the waypoints
  std::uint64_t seed = 1;                  // odometry and sonar noise
  double odometry_scale_error = 0.02;      // the odometry's travel per true m, less 1
  double odometry_drift = 0.03;            // its heading error per m driven, rad
  double odometry_noise = 0.01;            // its random travel error, m per sqrt(m)
  double odometry_turn_error = 0.01;       // its turn per true rad turned, less 1
  bool sonar_noise = true;                 // 10 mm range noise, 1 % drop-outs, 0.2 % spurious echoes
  std::optional<double> kidnap_after;      // seconds of driving after which the robot is carried off
  int kidnap_to_waypoint = 0;              // carried to this waypoint (> 0), facing the next
  bool global_start = false;               // the filter starts knowing nothing of the pose
  int slice = 0;                           // > 0: each step weighed this many particles at a time
};

// What the tour measured at each filter step.
struct TourSample {
  double time = 0.0;            // s of driving
  Pose truth = Pose::Zero();    // where the robot really was, m, m, rad
  Pose estimate = Pose::Zero(); // where the filter believed it was
  double filter_error = 0.0;    // |estimate - truth|, m
  double filter_heading = 0.0;  // |estimate - truth| of the heading, rad
  double odometry_error = 0.0;  // |odometry - truth| (the odometry frame is the map's at the start), m
  double odometry_heading = 0.0;// rad
  int particles = 0;            // the filter's count after the step
  double step_cpu = 0.0;        // the step's thread CPU time, s (with slices: the costliest part)
  int scouts_fired = 0;         // times a scout fired since the start (ParticleFilter::scouts_fired())
};

std::vector<TourSample> run_tour(const Lab& lab, const TourSpec& spec, const FilterParams& params = {});

// The simulator's own odometry noise (robuterd --sim --odometry-noise: wheel scales +-0.2 %,
// 2 mm per sqrt(m), slip 0.2 %), as this tour's model has it: a heading drift of 0.4 % of the
// travel over the 0.60 m wheel base, no scale error on straight runs or turns in place.
void use_simulator_odometry_noise(TourSpec& spec);

// Round both rooms of worlds/default.toml through the 90 cm door, clear of the boxes, from (1.5, 1.5).
TourSpec lab_loop(std::uint64_t seed = 1);

// Round the corridors of worlds/building_floor.toml (64 x 40 m): the east-west corridor end to
// end and corridors a and b up and down, about 225 m a lap, from corridor-ew-1's centre.
TourSpec floor_loop(std::uint64_t seed = 1);

// The first time (s of driving, from `after` on) from which the filter stays within 0.2 m and
// 10 degrees of the truth for ten steps running; -1 if it never does.
double found_after(const std::vector<TourSample>& samples, double after = 0.0);

// The q-quantile (0..1) of values.
double quantile(std::vector<double> values, double q);

}  // namespace robuter::loc::test
