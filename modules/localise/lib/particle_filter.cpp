// SPDX-License-Identifier: GPL-3.0-or-later
// The particle filter (particle_filter.hpp).
#include "modules/localise/lib/particle_filter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Eigenvalues>

namespace robuter::loc {
namespace {
constexpr int kNearbyDraws = 32;  // tries for a free pose near the anchor before drawing from the set
constexpr double kPromiseCell = 0.10;       // the promise cache's cell side, m
constexpr double kPromiseHeading = 0.0349;  // and its heading bin, rad (2°)
constexpr int kPromiseProbes = 16;          // slots tried before the answer is worked out uncached
static_assert(ParticleFilter::kMaxReadings <= 32, "promised() keeps one bit per reading");
}  // namespace

ParticleFilter::ParticleFilter(const DistanceField& field, const FilterParams& params, std::uint64_t seed)
    : field_(field), params_(params), rng_(seed), bins_(std::max(1, params.max_particles)),
      arc_(arc_table(params.sonar)), cone_(cone_table(params.sonar)), cells_(std::max(1, params.max_particles)) {
  params_.max_particles = std::max(1, params_.max_particles);
  params_.min_particles = std::clamp(params_.min_particles, 1, params_.max_particles);
  const auto n = static_cast<std::size_t>(params_.max_particles);
  particles_.resize(n);
  next_.resize(n);
  cdf_.resize(n);
  log_lik_.resize(n);
  std::size_t slots = 1;
  while (slots < 2 * n) slots <<= 1;  // a power of two, at least twice the particles
  promise_keys_.assign(slots, 0);
  promise_bits_.assign(slots, 0);
  const auto& g = field_.geometry();
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x)
      if (field_.cell(x, y) >= params_.body_clearance)
        free_.push_back(static_cast<std::uint32_t>(y * g.width + x));
}

void ParticleFilter::set_pose(const Pose& mean, const Eigen::Vector3d& sigma) {
  std::normal_distribution<double> unit(0.0, 1.0);
  stepping_ = false;  // a step under way is dropped: its particles are replaced
  count_ = params_.max_particles;
  for (int i = 0; i < count_; ++i) {
    auto& p = particles_[static_cast<std::size_t>(i)];
    p.pose = Pose(mean.x() + sigma.x() * unit(rng_), mean.y() + sigma.y() * unit(rng_),
                  wrap_angle(mean.z() + sigma.z() * unit(rng_)));
    p.weight = 1.0 / count_;
  }
  w_slow_ = w_fast_ = 0.0;
  anchor_ = Pose(mean.x(), mean.y(), wrap_angle(mean.z()));
  since_anchor_ = 0.0;
  update_estimate();
  place_scouts(true);  // scouts start afresh about the given pose
}

double ParticleFilter::recovery_radius() const {
  return params_.recover_within + params_.recover_growth * since_anchor_;
}

bool ParticleFilter::random_nearby_pose(Pose& out) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double r = recovery_radius();
  for (int k = 0; k < kNearbyDraws; ++k) {
    Eigen::Vector2d p;
    if (u(rng_) < params_.recover_along_share) {  // along the heading's line, a little across it
      const double along = r * (2.0 * u(rng_) - 1.0);
      const double across = params_.recover_cross_sigma * std::normal_distribution<double>(0.0, 1.0)(rng_);
      const Eigen::Vector2d dir = heading_line();
      p = Eigen::Vector2d(anchor_.x(), anchor_.y()) + along * dir + across * Eigen::Vector2d(-dir.y(), dir.x());
    } else {
      const double d = r * std::sqrt(u(rng_)), a = 2.0 * std::numbers::pi * u(rng_);
      p = Eigen::Vector2d(anchor_.x() + d * std::cos(a), anchor_.y() + d * std::sin(a));
    }
    if (!fits(p)) continue;
    // Most about the estimate's heading (a kidnapping carries the robot more than it turns it:
    // the cloud's heading is the best guess even when its place is lost); the rest any heading.
    const double heading = u(rng_) < params_.recover_heading_share
                               ? estimate_.pose.z() + params_.recover_heading_sigma * std::normal_distribution<double>(0.0, 1.0)(rng_)
                               : 2.0 * std::numbers::pi * u(rng_);
    out = Pose(p.x(), p.y(), wrap_angle(heading));
    return true;
  }
  return false;
}

Pose ParticleFilter::random_free_pose() {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto& g = field_.geometry();
  if (free_.empty()) return Pose::Zero();
  const auto k = static_cast<std::size_t>(u(rng_) * static_cast<double>(free_.size())) % free_.size();
  const auto cell = free_[k];
  const int cx = static_cast<int>(cell % static_cast<std::uint32_t>(g.width));
  const int cy = static_cast<int>(cell / static_cast<std::uint32_t>(g.width));
  return Pose(g.origin.x() + (cx + u(rng_)) * g.resolution, g.origin.y() + (cy + u(rng_)) * g.resolution,
              wrap_angle(2.0 * std::numbers::pi * u(rng_)));
}

void ParticleFilter::set_global() {
  stepping_ = false;
  count_ = params_.max_particles;
  for (int i = 0; i < count_; ++i) {
    auto& p = particles_[static_cast<std::size_t>(i)];
    p.pose = random_free_pose();
    p.weight = 1.0 / count_;
  }
  w_slow_ = w_fast_ = 0.0;
  since_anchor_ = std::numeric_limits<double>::infinity();  // anywhere: recovery draws globally
  update_estimate();
  place_scouts(true);
}

bool ParticleFilter::step(const Pose& odometry, std::span<const SonarReading> readings) {
  if (!begin_step(odometry, readings)) return false;
  return weigh_some(count_ + scout_count_);
}

void ParticleFilter::rebase(const Pose& odometry) {
  if (!odometry.allFinite()) return;
  last_odometry_ = odometry;
  have_odometry_ = true;
}

// A non-finite odometry is no motion: refused, the last one kept.
bool ParticleFilter::begin_step(const Pose& odometry, std::span<const SonarReading> readings) {
  if (stepping_ || !odometry.allFinite()) return false;
  if (!have_odometry_) {
    last_odometry_ = odometry;
    have_odometry_ = true;
    return false;
  }
  const OdometryStep s = odometry_step(last_odometry_, odometry);
  const double turned = std::abs(wrap_angle(odometry.z() - last_odometry_.z()));
  if (std::abs(s.trans) < params_.update_distance && turned < params_.update_angle) return false;
  last_odometry_ = odometry;
  since_anchor_ += std::abs(s.trans);
  for (int i = 0; i < count_; ++i) {
    auto& p = particles_[static_cast<std::size_t>(i)];
    p.pose = sample_motion(p.pose, s, params_.motion, rng_);
  }
  for (int i = 0; i < scout_count_; ++i) {
    auto& sc = scouts_[static_cast<std::size_t>(i)];
    sc.pose = move_pose(sc.pose, s);
    sc.free = i == 0 || fits(sc.pose.head<2>());
  }
  kept_count_ = informative_count_ = 0;
  for (const auto& r : readings) {
    const bool echo = informative(r, params_.sonar);
    if ((!echo && !silent(r, params_.sonar)) || kept_count_ == kMaxReadings) continue;
    kept_[static_cast<std::size_t>(kept_count_++)] =
        Kept{r.mount, Eigen::Vector2d(std::cos(r.direction), std::sin(r.direction)), r.range, !echo,
             echo ? echo_within(r.range, params_.sonar) : silence_within(r.range, params_.sonar)};
    if (echo) ++informative_count_;
  }
  std::fill(promise_keys_.begin(), promise_keys_.end(), 0);
  stepping_ = true;
  weighed_ = traced_ = scouts_weighed_ = 0;
  best_log_ = -1e300;
  likelihood_sum_ = 0.0;
  return true;
}

void ParticleFilter::aim(const Pose& pose) {
  const double c = std::cos(pose.z()), sn = std::sin(pose.z());
  Eigen::Matrix2d turn;
  turn << c, -sn, sn, c;
  const Eigen::Vector2d at(pose.x(), pose.y());
  for (int k = 0; k < kept_count_; ++k) {
    const auto i = static_cast<std::size_t>(k);
    beams_[i] = Beam{at + turn * kept_[i].mount, turn * kept_[i].axis};
  }
}

std::uint32_t ParticleFilter::promised(const Pose& pose) {
  const auto bin = [](double v, double side) { return static_cast<int>(std::floor(v / side)); };
  // The cell's bins, and a top bit so that no key is 0 (empty).
  const std::uint64_t key = (std::uint64_t{1} << 63) |
                            pack_bins(bin(pose.x(), kPromiseCell), bin(pose.y(), kPromiseCell), bin(pose.z(), kPromiseHeading));
  const std::size_t mask = promise_keys_.size() - 1;
  std::size_t slot = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 32) & mask;
  bool vacant = false;  // slot is free for this key (else the probes found none: not cached)
  for (int probe = 0; probe < kPromiseProbes; ++probe, slot = (slot + 1) & mask) {
    if (promise_keys_[slot] == key) return promise_bits_[slot];
    if (promise_keys_[slot] == 0) {
      vacant = true;
      break;
    }
  }
  ++traced_;
  std::uint32_t bits = 0;
  for (int k = 0; k < kept_count_; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (promises_echo(field_, beams_[i].origin, beams_[i].axis, kept_[i].within, params_.sonar, cone_))
      bits |= std::uint32_t{1} << k;
  }
  if (vacant) {
    promise_keys_[slot] = key;
    promise_bits_[slot] = bits;
  }
  return bits;
}

double ParticleFilter::log_likelihood(const Pose& pose) {
  double l = field_.at(Eigen::Vector2d(pose.x(), pose.y())) < params_.body_clearance ? std::log(params_.inside_weight) : 0.0;
  aim(pose);
  const std::uint32_t told = promised(pose);
  for (int k = 0; k < kept_count_; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const bool against = (told >> k) & 1u;
    if (kept_[i].silence) {
      if (against) l += std::log(promise_factor(true, true, params_.sonar));
      continue;
    }
    l += std::log(arc_likelihood(field_, beams_[i].origin, beams_[i].axis, kept_[i].range, params_.sonar, arc_) *
                  promise_factor(false, against, params_.sonar));
  }
  return l;
}

bool ParticleFilter::weigh_some(int n, int traces) {
  if (!stepping_) return false;
  const int traced_before = traced_;
  int done = 0;  // particles and scouts weighed in this call
  const auto may = [&] { return done < n && (done == 0 || traced_ - traced_before < traces); };
  for (; weighed_ < count_ && may(); ++weighed_, ++done) {
    const auto k = static_cast<std::size_t>(weighed_);
    const double l = log_likelihood(particles_[k].pose);
    log_lik_[k] = l;
    best_log_ = std::max(best_log_, l);
    if (informative_count_ > 0) likelihood_sum_ += std::exp(l / informative_count_);
  }
  for (; weighed_ == count_ && scouts_weighed_ < scout_count_ && may(); ++scouts_weighed_, ++done) {
    auto& sc = scouts_[static_cast<std::size_t>(scouts_weighed_)];
    if (sc.free) sc.log_lik = log_likelihood(sc.pose);
  }
  if (weighed_ < count_ || scouts_weighed_ < scout_count_) return false;
  finish_weighing();
  weigh_scouts();
  update_estimate();  // from the weighed particles, before resampling draws from them
  resample();
  estimate_.particles = count_;
  place_scouts(false);
  stepping_ = false;
  return true;
}

void ParticleFilter::finish_weighing() {
  if (informative_count_ >= params_.recovery_readings && count_ > 0) {
    const double mean_lik = likelihood_sum_ / count_;  // the per-reading geometric mean, averaged
    w_slow_ = w_slow_ == 0.0 ? mean_lik : w_slow_ + params_.alpha_slow * (mean_lik - w_slow_);
    w_fast_ = w_fast_ == 0.0 ? mean_lik : w_fast_ + params_.alpha_fast * (mean_lik - w_fast_);
  }
  double total = 0.0;
  for (int i = 0; i < count_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    particles_[k].weight = std::exp(params_.likelihood_power * (log_lik_[k] - best_log_));
    total += particles_[k].weight;
  }
  for (int i = 0; i < count_; ++i) particles_[static_cast<std::size_t>(i)].weight /= total;
}

void ParticleFilter::weigh_scouts() {
  scout_fired_ = -1;
  if (scout_count_ == 0) return;
  const double reference = scouts_[0].log_lik;
  // A step of a few echoes is no evidence (recovery_readings: the rule augmented MCL's averages
  // follow). In a room whose walls are mostly out of reach, such steps fired scouts at unmapped
  // furniture's echoes and sent two of #17's routes astray (docs/LOCALISATION.md, "Scouts").
  const bool counts = informative_count_ >= params_.recovery_readings;
  double most = params_.scout_threshold;
  for (int i = 1; i < scout_count_; ++i) {
    auto& sc = scouts_[static_cast<std::size_t>(i)];
    if (!sc.free) {
      sc.evidence = 0.0;
      continue;
    }
    if (counts)
      sc.evidence = std::max(0.0, sc.evidence + params_.likelihood_power * (sc.log_lik - reference) - params_.scout_drift);
    if (sc.evidence > 0.0 && sc.evidence >= most) {  // (a threshold of 0: no scout fires on none)
      most = sc.evidence;
      scout_fired_ = i;
    }
  }
  if (scout_fired_ < 0) return;
  ++scouts_fired_;
  // The draws go to every scout with evidence, by its odds against the one that fired: evidence
  // against the estimate's place is often evidence for several others alike.
  double acc = 0.0;
  for (int i = 0; i < scout_count_; ++i) {
    const auto& sc = scouts_[static_cast<std::size_t>(i)];
    acc += i > 0 && sc.evidence > 0.0 ? std::exp(sc.evidence - most) : 0.0;
    scout_cdf_[static_cast<std::size_t>(i)] = acc;
  }
}

void ParticleFilter::place_scouts(bool afresh) {
  const int wanted = std::clamp(params_.scouts, 0, kMaxScouts);
  // Afresh too after one fired (its evidence is spent) and after a search (none were out).
  const bool fresh = afresh || scout_fired_ >= 0 || scout_count_ != wanted + 1;
  if (afresh) scout_fired_ = -1;
  if (wanted == 0 || count_ == 0 || !std::isfinite(since_anchor_)) {  // none, or a global search
    scout_count_ = 0;
    return;
  }
  const Pose& e = estimate_.pose;
  const Eigen::Vector2d dir = heading_line();
  scout_count_ = wanted + 1;
  scouts_[0] = Scout{e, 0.0, 0.0, true};
  for (int i = 1; i < scout_count_; ++i) {
    auto& sc = scouts_[static_cast<std::size_t>(i)];
    if (!fresh && sc.evidence > 0.0) continue;  // it follows the odometry while it gathers evidence
    const int k = (i + 1) / 2;                   // 1, 1, 2, 2, ...: ahead and behind in turn
    const double along = (i % 2 == 1 ? 1.0 : -1.0) * params_.scout_spacing * k;
    const Pose p(e.x() + along * dir.x(), e.y() + along * dir.y(), e.z());
    sc = Scout{p, 0.0, 0.0, fits(p.head<2>())};
  }
}

Eigen::Vector2d ParticleFilter::heading_line() const {
  return {std::cos(estimate_.pose.z()), std::sin(estimate_.pose.z())};
}

bool ParticleFilter::fits(const Eigen::Vector2d& at) const {
  return field_.contains(at) && field_.at(at) >= params_.body_clearance;
}

Pose ParticleFilter::about_scout() {
  std::normal_distribution<double> unit(0.0, 1.0);
  const double x = std::uniform_real_distribution<double>(0.0, scout_cdf_[static_cast<std::size_t>(scout_count_ - 1)])(rng_);
  const auto at = std::upper_bound(scout_cdf_.begin(), scout_cdf_.begin() + scout_count_, x) - scout_cdf_.begin();
  const Pose& c = scouts_[static_cast<std::size_t>(std::min<std::ptrdiff_t>(at, scout_count_ - 1))].pose;
  return Pose(c.x() + params_.scout_sigma_xy * unit(rng_), c.y() + params_.scout_sigma_xy * unit(rng_),
              wrap_angle(c.z() + params_.scout_sigma_theta * unit(rng_)));
}

void ParticleFilter::resample() {
  if (count_ == 0) return;
  double acc = 0.0;
  for (int i = 0; i < count_; ++i) {
    acc += particles_[static_cast<std::size_t>(i)].weight;
    cdf_[static_cast<std::size_t>(i)] = acc;
  }
  // Augmented MCL's share of random particles, only past inject_above: the small dips of tracking
  // (the share stays at 0.00 along the floor's corridors) are no kidnapping.
  const double share = w_slow_ > 0.0 ? std::max(0.0, 1.0 - w_fast_ / w_slow_) : 0.0;
  const double inject = share > params_.inject_above ? share : 0.0;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // Recovery nearby (docs/LOCALISATION.md): within recovery_radius() of the last compact estimate
  // while that disc is smaller than the map; over the whole map past it (and after set_global).
  const auto& g = field_.geometry();
  const bool global = !(recovery_radius() < g.resolution * std::hypot(g.width, g.height));
  bins_.clear();
  injected_ = 0;
  int n = 0;
  int needed_for = -1;  // the bins kld_needed() was last worked out for
  double needed = 0.0;  // and what it asked for
  for (;;) {
    Pose pose;
    const bool scouting = scout_fired_ >= 0 && u(rng_) < params_.scout_share;
    const bool injecting = !scouting && u(rng_) < inject;
    if (scouting) {
      pose = about_scout();
      ++injected_;
    } else if (injecting && global) {
      pose = random_free_pose();
      ++injected_;
    } else if (injecting && random_nearby_pose(pose)) {
      ++injected_;
    } else {
      const double x = u(rng_) * acc;
      const auto it = std::upper_bound(cdf_.begin(), cdf_.begin() + count_, x);
      const auto k = std::min<std::ptrdiff_t>(it - cdf_.begin(), count_ - 1);
      pose = particles_[static_cast<std::size_t>(k)].pose;
    }
    next_[static_cast<std::size_t>(n)] = Particle{pose, 0.0};
    ++n;
    bins_.insert(static_cast<int>(std::floor(pose.x() / params_.bin_xy)),
                 static_cast<int>(std::floor(pose.y() / params_.bin_xy)),
                 static_cast<int>(std::floor(pose.z() / params_.bin_theta)));
    if (bins_.size() != needed_for) {  // the bound grows with the bins: worked out when they do
      needed_for = bins_.size();
      needed = std::max<double>(params_.min_particles, kld_needed(needed_for, params_.kld_epsilon, params_.kld_z));
    }
    if (n >= params_.max_particles || n >= needed) break;
  }
  std::swap(particles_, next_);
  count_ = n;
  for (int i = 0; i < count_; ++i) particles_[static_cast<std::size_t>(i)].weight = 1.0 / count_;
}

void ParticleFilter::update_estimate() {
  Estimate e;
  e.particles = count_;
  if (count_ == 0) {
    estimate_ = e;
    return;
  }
  const double cell = params_.cluster_cell;
  const auto cx = [cell](const Pose& p) { return static_cast<int>(std::floor(p.x() / cell)); };
  const auto cy = [cell](const Pose& p) { return static_cast<int>(std::floor(p.y() / cell)); };
  cells_.clear();
  for (int i = 0; i < count_; ++i) {
    const auto& p = particles_[static_cast<std::size_t>(i)].pose;
    cells_.add(cx(p), cy(p), 0);
  }
  // The densest 3 x 3 block of cells, by the particles in it (the block about each occupied cell
  // tried, in the order the particles first filled them: the first densest wins).
  int best = -1, bx = 0, by = 0;
  cells_.for_each([&](int x, int y, int, int) {
    int n = 0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) n += cells_.count(x + dx, y + dy, 0);
    if (n > best) {
      best = n;
      bx = x;
      by = y;
    }
  });
  double w = 0.0, sx = 0.0, sy = 0.0, sc = 0.0, ss = 0.0;
  const auto in_block = [&](const Pose& p) { return std::abs(cx(p) - bx) <= 1 && std::abs(cy(p) - by) <= 1; };
  for (int i = 0; i < count_; ++i) {
    const auto& p = particles_[static_cast<std::size_t>(i)];
    if (!in_block(p.pose)) continue;
    w += p.weight;
    sx += p.weight * p.pose.x();
    sy += p.weight * p.pose.y();
    sc += p.weight * std::cos(p.pose.z());
    ss += p.weight * std::sin(p.pose.z());
  }
  if (w <= 0.0) {  // the block's particles all weigh nothing: keep the last estimate's pose
    e.pose = estimate_.pose;
    estimate_ = e;
    return;
  }
  e.pose = Pose(sx / w, sy / w, std::atan2(ss, sc));
  e.cluster_weight = w;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (int i = 0; i < count_; ++i) {
    const auto& p = particles_[static_cast<std::size_t>(i)];
    if (!in_block(p.pose)) continue;
    const Eigen::Vector3d d(p.pose.x() - e.pose.x(), p.pose.y() - e.pose.y(), wrap_angle(p.pose.z() - e.pose.z()));
    cov += (p.weight / w) * d * d.transpose();
  }
  e.covariance = cov;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov.topLeftCorner<2, 2>(), Eigen::EigenvaluesOnly);
  e.compact = w >= params_.compact_weight && std::sqrt(std::max(0.0, eig.eigenvalues()(1))) <= params_.compact_major &&
              std::sqrt(std::max(0.0, cov(2, 2))) <= params_.compact_heading;
  if (e.compact) {  // recovery's anchor: where the pose was last known
    anchor_ = e.pose;
    since_anchor_ = 0.0;
  }
  estimate_ = e;
}

}  // namespace robuter::loc
