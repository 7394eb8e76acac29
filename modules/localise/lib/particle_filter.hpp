// SPDX-License-Identifier: GPL-3.0-or-later
// Monte Carlo localisation on a distance field: odometry motion, sonar weights, KLD resampling.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "modules/localise/lib/distance_field.hpp"
#include "modules/localise/lib/kld_bins.hpp"
#include "modules/localise/lib/motion_model.hpp"
#include "modules/localise/lib/sonar_likelihood.hpp"

namespace robuter::loc {

// The filter's constants (docs/LOCALISATION.md, "The filter").
struct FilterParams {
  int min_particles = 200;         // KLD-sampling never keeps fewer
  int max_particles = 2000;        // nor more (every buffer is this size, from construction)
  double kld_epsilon = 0.05;       // KLD-sampling's error bound
  double kld_z = 2.33;             // its upper standard normal quantile (1 - delta = 0.99)
  double bin_xy = 0.25;            // KLD bin side, m
  double bin_theta = 0.1745;       // KLD bin width, rad (10°)
  double update_distance = 0.10;   // the filter steps once the odometry has moved this far, m
  double update_angle = 0.10;      // or turned this much, rad
  double alpha_slow = 0.001;       // augmented MCL: the slow average of the measurement likelihood
  double alpha_fast = 0.1;         // and the fast one; fast < slow injects random particles
  double body_clearance = 0.30;    // an axle nearer than this to a mapped wall is not a pose, m
  double inside_weight = 0.02;     // the likelihood factor of such a pose
  double cluster_cell = 1.0;       // the estimate's cells, m: it is the mean of the densest 3 x 3
                                   // cells' particles, not of the whole cloud
  double inject_above = 0.1;       // augmented MCL injects only when its share 1 - w_fast / w_slow
                                   // is above this (docs/LOCALISATION.md, "Recovery nearby")
  double compact_weight = 0.6;     // the estimate is compact (one cluster: "tracking") with at
  double compact_major = 0.5;      // least this share of the weight, a 1-sigma ellipse's
  double compact_heading = 0.26;   // semi-major axis at most this (m) and a heading's standard
                                   // deviation at most this (rad, 15°)
  double recover_within = 4.0;     // recovery draws its random particles within this of the last
                                   // compact estimate, m (docs/LOCALISATION.md, "Recovery nearby")
  double recover_growth = 1.0;     // and the radius grows by this per metre driven since, m/m
  double recover_heading_share = 0.75;  // the share of them drawn about the estimate's heading,
  double recover_heading_sigma = 0.26;  // this far (rad, 15°, one sigma); the rest any heading
  double recover_along_share = 0.5;  // the share of them drawn along the estimate's heading line
  double recover_cross_sigma = 0.25; // (a corridor's axis: a carry along it is what the ring cannot
                                     // tell), this far across it (m, one sigma); the rest in the disc
  int recovery_readings = 6;       // a step with fewer informative readings leaves augmented MCL's
                                   // averages as they were: a few echoes (a room whose walls are
                                   // out of reach) are no measure of whether the robot is lost
  double likelihood_power = 0.5;   // each reading's likelihood to this power: the ring's 24
                                   // readings of one step are not independent (AMCL's answer is
                                   // to use fewer beams; this keeps them all and flattens each)
  // Scouts (docs/LOCALISATION.md, "Scouts along the heading line"): single poses at
  // scout_spacing steps along the estimate's heading line, half ahead and half behind, moved by
  // the odometry and weighed every step like a particle. Each sums its evidence against the
  // estimate (a CUSUM of the log-likelihood ratio, times likelihood_power, less scout_drift a
  // step, never below 0); one whose sum reaches scout_threshold draws scout_share of the next
  // particles about itself, and the filter decides. A scout with no evidence is placed again on
  // the line each step. A carry along a corridor, which the ring cannot tell while the walls run
  // on, is what they watch for: a door or a crossing is evidence for the one where the robot is.
  int scouts = 16;                 // how many (0: none; at most kMaxScouts)
  double scout_spacing = 0.5;      // m between neighbours on the line
  double scout_threshold = 6.0;    // evidence that fires a scout
  double scout_drift = 0.25;       // evidence taken off each scout's sum a step (the prior that
                                   // the estimate is right)
  double scout_share = 0.5;        // the share of the next particles drawn about a scout that fired
  double scout_sigma_xy = 0.15;    // their spread about it, m (one sigma)
  double scout_sigma_theta = 0.09; // and in heading, rad (5°)
  MotionNoise motion;              // the odometry model's noise
  SonarModelParams sonar;          // the ring's model
};

// One hypothesis.
struct Particle {
  Pose pose = Pose::Zero();  // x, y (m), theta (rad) in the map frame
  double weight = 0.0;       // normalised: the particles' weights add up to 1
};

// What the filter believes.
// What the filter believes: the densest part of the cloud (a cloud split between two places, or
// with random particles injected, would put a mean of all in neither).
struct Estimate {
  Pose pose = Pose::Zero();                                 // weighted mean of the densest 3 x 3
                                                            // cluster cells (theta: circular mean)
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity(); // of x (m), y (m), theta (rad), over those
  double cluster_weight = 0.0;                              // the weight those particles hold, 0..1:
                                                            // well below 1, the pose is ambiguous
  int particles = 0;                                        // how many it keeps now
  bool compact = false;                                     // one cluster, within the compact_*
                                                            // bounds: the pose is known
};

// A single pose the filter watches beside its cloud (FilterParams' scouts).
struct Scout {
  Pose pose = Pose::Zero();  // map frame
  double log_lik = 0.0;      // at the step's weighing
  double evidence = 0.0;     // its CUSUM against the estimate
  bool free = false;         // on the map, body_clearance from every wall: else not weighed (open
                             // space off the map explains any echo as well as clutter does)
};

class ParticleFilter {
 public:
  static constexpr int kMaxScouts = 16;
  // Allocates every buffer (max_particles particles, the field's free cells); nothing after.
  ParticleFilter(const DistanceField& field, const FilterParams& params, std::uint64_t seed);

  // A Gaussian cloud of max_particles about `mean` with standard deviations `sigma` (m, m, rad).
  void set_pose(const Pose& mean, const Eigen::Vector3d& sigma);
  // Global localisation: max_particles spread over the map's free cells, any heading.
  void set_global();

  static constexpr int kMaxReadings = 32;  // ranges kept per step (the ring's 24, the pan-tilt's)

  // Feeds the odometry's pose (its own frame) and the ring's last readings (robot frame). The
  // filter steps (moves every particle by the odometry since its last step, weighs, resamples)
  // once the odometry has moved update_distance or turned update_angle; true when it stepped.
  bool step(const Pose& odometry, std::span<const SonarReading> readings);

  // The same step in parts, for a caller with a budget per activation: begin_step() moves the
  // particles and keeps the readings (true when a step begins; false while one is under way or
  // the robot has not moved enough), weigh_some() weighs up to `n` more particles (then the
  // scouts, which count in `n` too) and, once all are weighed, resamples (true when the step is
  // done). step() is begin_step() and one weigh_some() of every particle and scout: the same
  // draws, the same result.
  bool begin_step(const Pose& odometry, std::span<const SonarReading> readings);
  // The odometry jumped without the robot moving (AC set it): the next step measures the motion
  // from `odometry`. A step under way goes on (its particles have moved already).
  void rebase(const Pose& odometry);
  // weigh_some(n, traces) also ends the call once `traces` particles needed the map's promises
  // traced (promised(): a pose in a cell no particle of this step was weighed in), the costly
  // part: a cloud that tracks shares a few dozen cells, a global search's hardly any. Each call
  // weighs one particle (or scout) at least.
  bool weigh_some(int n, int traces = std::numeric_limits<int>::max());
  bool stepping() const { return stepping_; }
  // Of the step under way (or the last one): particles weighed, and how many of them needed the
  // map's promises traced.
  int weighed() const { return weighed_; }
  int traced() const { return traced_; }

  // As of the last step (or set_pose / set_global).
  const Estimate& estimate() const { return estimate_; }
  std::span<const Particle> particles() const { return {particles_.data(), static_cast<std::size_t>(count_)}; }
  // The average measurement likelihoods of augmented MCL (per reading), slow and fast.
  double w_slow() const { return w_slow_; }
  double w_fast() const { return w_fast_; }
  // Particles drawn at random (free cells, nearby or about a scout) at the last step.
  int injected() const { return injected_; }
  // The scouts (the first is the estimate they are weighed against), as of the last step.
  std::span<const Scout> scouts() const { return {scouts_.data(), static_cast<std::size_t>(scout_count_)}; }
  // How many times a scout fired since construction.
  int scouts_fired() const { return scouts_fired_; }
  // Cells of the map where the robot fits (body_clearance from every wall): 0 and there is no pose.
  std::size_t free_cells() const { return free_.size(); }
  // The radius recovery draws its random particles in now, m (infinite after set_global()).
  double recovery_radius() const;
  const FilterParams& params() const { return params_; }

 private:
  // One informative reading or silence, its direction worked out once per step.
  struct Kept {
    Eigen::Vector2d mount;  // transducer in the robot frame, m
    Eigen::Vector2d axis;   // beam axis in the robot frame, unit
    double range = 0.0;     // m (a silence: its reach)
    bool silence = false;   // no echo within range
    double within = 0.0;    // how near an echo the map promises tells against it, m
  };
  // A kept reading's transducer and beam axis in the map frame, for the particle being weighed.
  struct Beam {
    Eigen::Vector2d origin;  // m
    Eigen::Vector2d axis;    // unit
  };
  // Every kept reading's beam for a particle at `pose`, into beams_ (the one robot-to-map
  // transform of the readings).
  void aim(const Pose& pose);
  // Which of this step's readings the map tells against at `pose` (bit k: promises_echo() for
  // kept_[k] along beams_[k]), from the promise cache: poses in one cell of 0.1 m and 2° share the
  // answer of the first one weighed there (the margins are 0.3 m: a cloud that tracks fills a few
  // dozen cells).
  std::uint32_t promised(const Pose& pose);
  double log_likelihood(const Pose& pose);
  void finish_weighing();
  // The scouts' evidence from this step's weighing; scout_fired_ the one past the threshold.
  void weigh_scouts();
  // The estimate and the scouts with no evidence placed on its heading line; all of them
  // `afresh` (a pose or a search given) or after one fired; none while the filter searches the
  // whole map.
  void place_scouts(bool afresh);
  Pose about_scout();
  // The unit vector along the estimate's heading: the line scouts and recovery draws lie on.
  Eigen::Vector2d heading_line() const;
  // On the map, body_clearance from every wall: a place the robot fits (the one rule for scouts
  // and recovery draws).
  bool fits(const Eigen::Vector2d& at) const;
  void update_estimate();
  void resample();
  Pose random_free_pose();
  // A random free pose within recovery_radius() of the last compact estimate; false when a few
  // draws found none (the caller draws from the weighed particles instead).
  bool random_nearby_pose(Pose& out);

  const DistanceField& field_;
  FilterParams params_;
  std::mt19937_64 rng_;
  std::vector<Particle> particles_;  // the current set (max_particles slots, count_ used)
  std::vector<Particle> next_;       // resampling's output
  std::vector<double> cdf_;          // cumulative weights of the current set
  std::vector<double> log_lik_;      // per particle, at the last weighing
  std::vector<std::uint32_t> free_;  // cells whose centre is body_clearance from every wall
  KldBins bins_;                     // KLD-sampling's bins
  ArcTable arc_;                     // the sonar model's directions across the cone
  ArcTable cone_;                    // and the rays promises_echo() traces
  KldBins cells_;                    // the estimate's cluster cells and their particle counts
  Estimate estimate_;                // as of the last step
  std::array<Kept, kMaxReadings> kept_{};  // this step's informative readings and silences
  std::array<Beam, kMaxReadings> beams_{}; // and their beams for the particle being weighed
  int kept_count_ = 0;               // how many
  int informative_count_ = 0;        // how many of them are echoes
  std::vector<std::uint64_t> promise_keys_;  // the promise cache (open addressing, this step's):
  std::vector<std::uint32_t> promise_bits_;  // cell keys (0: empty) and their promised() bits
  bool stepping_ = false;            // a step is under way (particles moved, not all weighed)
  int weighed_ = 0;                  // particles weighed so far in this step
  int traced_ = 0;                   // promised() calls that traced the promises (not cached)
  double best_log_ = 0.0;            // the largest log-likelihood so far in this step
  double likelihood_sum_ = 0.0;      // sum of the per-reading geometric mean likelihoods so far
  int count_ = 0;                    // particles in use
  int injected_ = 0;                 // random particles at the last resampling
  double w_slow_ = 0.0;              // slow average likelihood per reading
  double w_fast_ = 0.0;              // fast average likelihood per reading
  Pose last_odometry_ = Pose::Zero();// the odometry at the last step
  bool have_odometry_ = false;       // step() has seen an odometry pose
  Pose anchor_ = Pose::Zero();       // the last compact estimate (or set_pose's mean)
  double since_anchor_ = 0.0;        // the odometry's travel since then, m (infinite: global)
  std::array<Scout, kMaxScouts + 1> scouts_{};  // [0]: the estimate; then the line's scouts
  std::array<double, kMaxScouts + 1> scout_cdf_{};  // their cumulative odds when one fired
  int scout_count_ = 0;              // in use (0: none)
  int scouts_weighed_ = 0;           // of this step
  int scout_fired_ = -1;             // the scout past the threshold at this step (-1: none)
  int scouts_fired_ = 0;             // how many times one fired
};

}  // namespace robuter::loc
