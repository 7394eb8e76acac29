// SPDX-License-Identifier: GPL-3.0-or-later
// The localisation tests' tour (lab_tour.hpp).
#include "tests/localise/lab_tour.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include <time.h>

#include "hal/sim/rng.hpp"
#include "hal/sim/sonar.hpp"
#include "hal/sim/sonar_layout.hpp"
#include "hal/sim/world_io.hpp"

namespace robuter::loc::test {

namespace {
double thread_cpu() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
}  // namespace

Lab load_lab(const std::string& file) {
  auto loaded = sim::load_world(std::string(ROBUTER_WORLDS_DIR) + "/" + file);
  if (!loaded) throw std::runtime_error("cannot load " + file);
  Lab lab{std::move(loaded.value()), {}};
  const auto& b = lab.world.bounds();
  FieldGeometry g;
  g.resolution = 0.05;
  g.origin = b.lo - Eigen::Vector2d(1.0, 1.0);
  g.width = static_cast<int>(std::ceil((b.hi.x() - b.lo.x() + 2.0) / g.resolution));
  g.height = static_cast<int>(std::ceil((b.hi.y() - b.lo.y() + 2.0) / g.resolution));
  std::vector<std::uint8_t> occ(static_cast<std::size_t>(g.width) * static_cast<std::size_t>(g.height), 0);
  for (const auto& s : lab.world.segments()) {
    const double len = (s.b - s.a).norm();
    const int n = std::max(1, static_cast<int>(std::ceil(len / 0.01)));
    for (int i = 0; i <= n; ++i) {
      const Eigen::Vector2d p = s.a + (s.b - s.a) * (static_cast<double>(i) / n);
      const int x = static_cast<int>(std::floor((p.x() - g.origin.x()) / g.resolution));
      const int y = static_cast<int>(std::floor((p.y() - g.origin.y()) / g.resolution));
      if (x >= 0 && y >= 0 && x < g.width && y < g.height) occ[static_cast<std::size_t>(y * g.width + x)] = 1;
    }
  }
  lab.field = DistanceField(g, occ, 2.0);
  return lab;
}

TourSpec lab_loop(std::uint64_t seed) {
  TourSpec s;
  s.waypoints = {{1.5, 1.5}, {3.0, 2.0}, {3.6, 3.0}, {5.4, 3.0}, {5.4, 2.4}, {6.6, 2.3},
                 {5.4, 4.0}, {5.4, 3.0}, {3.6, 3.0}, {1.5, 3.2}};
  s.start = Pose(1.5, 1.5, 0.0);
  s.seed = seed;
  return s;
}

void use_simulator_odometry_noise(TourSpec& spec) {
  spec.odometry_scale_error = 0.0;
  spec.odometry_drift = 0.004 / 0.60;
  spec.odometry_noise = 0.003;  // 2 mm per sqrt(m) of each wheel and the slip's spread
  spec.odometry_turn_error = 0.0;
}

TourSpec floor_loop(std::uint64_t seed) {
  TourSpec s;
  s.waypoints = {{6.0, 20.05},  {21.15, 20.05}, {21.15, 34.6}, {21.15, 5.45}, {21.15, 20.05},
                 {43.1, 20.05}, {43.1, 34.6},   {43.1, 5.45},  {43.1, 20.05}, {59.0, 20.05}};
  s.start = Pose(6.0, 20.05, 0.0);
  s.seed = seed;
  return s;
}

double found_after(const std::vector<TourSample>& samples, double after) {
  constexpr double kTenDegrees = 10.0 * std::numbers::pi / 180.0;
  for (std::size_t i = 0; i + 10 <= samples.size(); ++i) {
    if (samples[i].time < after) continue;
    bool stays = true;
    for (std::size_t j = i; j < i + 10; ++j)
      stays = stays && samples[j].filter_error < 0.2 && samples[j].filter_heading < kTenDegrees;
    if (stays) return samples[i].time;
  }
  return -1.0;
}

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto k = static_cast<std::size_t>(std::clamp(q, 0.0, 1.0) * static_cast<double>(values.size() - 1) + 0.5);
  return values[k];
}

std::vector<TourSample> run_tour(const Lab& lab, const TourSpec& spec, const FilterParams& params) {
  constexpr double dt = 0.1, speed = 0.4, turn_rate = 0.8;
  sim::SonarParams sp = sim::default_ring_params();
  if (spec.sonar_noise) {
    sp.noise_sigma = 0.010;
    sp.dropout_probability = 0.01;
    sp.spurious_probability = 0.002;
  }
  sim::SonarModel sonar(lab.world, sp);
  const auto layout = sim::default_ring_layout();
  sim::Rng sonar_rng(spec.seed * 7919 + 1);
  std::mt19937_64 odo_rng(spec.seed);
  std::normal_distribution<double> unit(0.0, 1.0);

  ParticleFilter filter(lab.field, params, spec.seed * 104729 + 3);
  if (spec.global_start) filter.set_global();
  else filter.set_pose(spec.start, Eigen::Vector3d(0.05, 0.05, 0.03));

  Pose truth = spec.start, odo = spec.start;
  std::vector<SonarReading> readings(layout.size());
  std::vector<TourSample> out;
  double time = 0.0;
  bool kidnapped = false;
  int tick = 0;
  const auto n_way = spec.waypoints.size();
  const std::size_t legs = n_way * static_cast<std::size_t>(spec.laps);
  for (std::size_t leg = 0; leg < legs; ++leg) {
    {
      const Eigen::Vector2d goal = spec.waypoints[(leg + 1) % n_way];
      for (int guard = 0; guard < 100000; ++guard) {
        const Eigen::Vector2d here(truth.x(), truth.y());
        const Eigen::Vector2d to = goal - here;
        if (to.norm() < 0.05) break;
        const double err = wrap_angle(std::atan2(to.y(), to.x()) - truth.z());
        double ds = 0.0, dth = 0.0;
        if (std::abs(err) > 0.15) dth = std::clamp(err, -turn_rate * dt, turn_rate * dt);
        else {
          ds = std::min(speed * dt, to.norm());
          dth = std::clamp(err, -turn_rate * dt, turn_rate * dt);
        }
        // The truth: an arc of length ds turning dth.
        const double mid = truth.z() + 0.5 * dth;
        truth = Pose(truth.x() + ds * std::cos(mid), truth.y() + ds * std::sin(mid), wrap_angle(truth.z() + dth));
        // The odometry: the same wheels' motion, misread.
        const double ods = ds * (1.0 + spec.odometry_scale_error) + spec.odometry_noise * std::sqrt(ds) * unit(odo_rng);
        const double odth = dth * (1.0 + spec.odometry_turn_error) + spec.odometry_drift * ds + 0.002 * std::sqrt(std::abs(dth)) * unit(odo_rng);
        const double omid = odo.z() + 0.5 * odth;
        odo = Pose(odo.x() + ods * std::cos(omid), odo.y() + ods * std::sin(omid), wrap_angle(odo.z() + odth));
        time += dt;
        if (spec.kidnap_after && !kidnapped && time >= *spec.kidnap_after) {
          // Carried to a waypoint, facing the next one; the tour goes on from there.
          const auto k = static_cast<std::size_t>(spec.kidnap_to_waypoint) % n_way;
          const Eigen::Vector2d next = spec.waypoints[(k + 1) % n_way] - spec.waypoints[k];
          truth = Pose(spec.waypoints[k].x(), spec.waypoints[k].y(), std::atan2(next.y(), next.x()));
          kidnapped = true;
          leg = (leg / n_way) * n_way + k - 1;  // the loop's ++leg makes it k
          break;
        }
        if (++tick % 2 != 0) continue;  // the ring's 24 ranges refresh every 0.2 s
        for (std::size_t s = 0; s < layout.size(); ++s) {
          const double r = sonar.measure(sim::Pose{truth.x(), truth.y(), truth.z()}, layout[s], &sonar_rng);
          readings[s] = SonarReading{layout[s].position, layout[s].direction, r};
        }
        double cpu0 = thread_cpu();
        double cpu = 0.0;
        if (spec.slice <= 0) {
          if (!filter.step(odo, readings)) continue;
          cpu = thread_cpu() - cpu0;
        } else {
          if (!filter.begin_step(odo, readings)) continue;
          for (bool done = false; !done;) {  // as the module will: the motion, then slices
            cpu = std::max(cpu, thread_cpu() - cpu0);
            cpu0 = thread_cpu();
            done = filter.weigh_some(spec.slice);
          }
          cpu = std::max(cpu, thread_cpu() - cpu0);
        }
        const Estimate e = filter.estimate();
        TourSample t;
        t.time = time;
        t.truth = truth;
        t.estimate = e.pose;
        t.filter_error = std::hypot(e.pose.x() - truth.x(), e.pose.y() - truth.y());
        t.filter_heading = std::abs(wrap_angle(e.pose.z() - truth.z()));
        t.odometry_error = std::hypot(odo.x() - truth.x(), odo.y() - truth.y());
        t.odometry_heading = std::abs(wrap_angle(odo.z() - truth.z()));
        t.particles = e.particles;
        t.step_cpu = cpu;
        t.scouts_fired = filter.scouts_fired();
        out.push_back(t);
      }
    }
  }
  return out;
}

}  // namespace robuter::loc::test
