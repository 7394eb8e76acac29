// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of the pure simulated world: simulated seconds per wall-clock second on the default
// world, robot stepped every 10 ms, all 24 ring sonars every 40 ms, the pan-tilt pair every 30 ms;
// then the realistic sonar model's cost per reading against the ideal one's, on the same poses,
// and how often its indirect paths change a reading.
#include <array>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <span>
#include <string>
#include <vector>

#include "hal/sim/robot.hpp"
#include "hal/sim/sonar_layout.hpp"
#include "hal/sim/sonar_presets.hpp"
#include "hal/sim/world_io.hpp"
#include "tests/support/wanderer.hpp"

using namespace robuter::sim;
namespace test = robuter::test;

namespace {

// A wandering robot: forward with a slight curve, turning on the spot when the front sensors
// report something near, so that it keeps moving around the default world's rooms.
struct Scenario {
  const World& world;                        // the world wandered in
  Robot robot;                               // the robot
  SonarModel ring;                           // ring sonar model (noisy)
  SonarModel ptu;                            // pan-tilt sonar model
  RingLayout layout = default_ring_layout(); // ring sensor mounts
  PanTiltMount mount;                        // pan-tilt mount
  Rng noise{1234};                           // sonar noise and manoeuvre durations
  std::array<double, kRingSensors> ranges{}; // last ring readings, m
  std::vector<Pose> visited;                 // every fourth ring reading's pose in the first 600 s (models compared)
  double pan = 0.0;         // pan direction, rad
  double pan_step = 0.0873; // 5° per firing
  long sonar_reads = 0;     // ring sensor evaluations
  long ptu_reads = 0;       // pan-tilt firings (two sensors each)

  // The robot at the world's start, noisy ring sonars, ideal pan-tilt sonars.
  explicit Scenario(const World& w)
      : world(w),
        robot(w, RobotParams{}, *w.start),
        ring(w, default_ring_params()),
        ptu(w, default_pan_tilt_params()) {
    SonarParams p = default_ring_params();
    p.noise_sigma = 0.01;
    p.spurious_probability = 0.01;
    ring.set_params(p);
  }

  test::Wanderer wanderer;  // forward, turning from what the front sensors hear

  // One 10 ms tick number `k`.
  void tick(long k) {
    if (k % 4 == 0) {
      if (k % 16 == 0 && k < 60000) visited.push_back(robot.pose());  // the first 600 s: the same poses every run
      for (int i = 0; i < kRingSensors; ++i) ranges[i] = ring.measure(robot.pose(), layout[i], &noise);
      sonar_reads += kRingSensors;
      robot.command(wanderer.decide(k, ranges, robot.bumper(), noise));
    }
    if (k % 3 == 0) {
      measure_pan_tilt(ptu, robot.pose(), mount, pan, &noise);
      ++ptu_reads;
      pan += pan_step;
      if (pan > kPi / 2 || pan < -kPi / 2) pan_step = -pan_step;
    }
    robot.step(0.01);
  }
};

// The ring fired node by node (4 sensors together) at every pose with `model`; readings into out.
void fire_ring(SonarModel& model, const std::vector<Pose>& poses, const RingLayout& layout, Rng* rng,
               std::vector<double>& out) {
  std::size_t k = 0;
  for (const Pose& pose : poses) {
    for (std::size_t n = 0; n < layout.size(); n += 4, k += 4) {
      model.measure_firing(pose, std::span<const SonarMount>(layout).subspan(n, 4), std::span<double>(out).subspan(k, 4), rng);
    }
  }
}

// CPU seconds of the best of three runs of fire_ring.
double best_cpu(SonarModel& model, const std::vector<Pose>& poses, const RingLayout& layout, Rng* rng,
                std::vector<double>& out) {
  double best = 1e30;
  for (int run = 0; run < 3; ++run) {
    const std::clock_t c0 = std::clock();
    fire_ring(model, poses, layout, rng, out);
    best = std::min(best, static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
  }
  return best;
}

// The realistic model against the ideal one on the poses a wander visited: CPU per reading
// (target: at most 2×, issue #19) and the share of readings its indirect paths change.
void compare_models(const World& world, const std::vector<Pose>& poses) {
  const RingLayout layout = default_ring_layout();
  SonarParams ideal_p = default_ring_params();
  apply_sonar_preset(SonarPreset::ideal, ideal_p);
  SonarParams real_p = default_ring_params();
  apply_sonar_preset(SonarPreset::realistic, real_p);
  SonarParams paths_p = ideal_p;  // the realistic model's paths without its random effects
  paths_p.multipath = paths_p.crosstalk = true;
  SonarModel ideal(world, ideal_p), realistic(world, real_p), paths(world, paths_p);
  const std::size_t n = poses.size() * layout.size();
  std::vector<double> a(n), b(n), c(n);
  Rng rng(99);
  const double t_ideal = best_cpu(ideal, poses, layout, nullptr, a);
  const double t_real = best_cpu(realistic, poses, layout, &rng, b);
  fire_ring(paths, poses, layout, nullptr, c);
  long silence_to_echo = 0, longer = 0, shorter = 0, shorter_far = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const bool ia = a[i] > 0.0, ic = c[i] > 0.0;
    if (ic && !ia) ++silence_to_echo;
    if (ic && ia && c[i] > a[i] + 1e-9) ++longer;
    if (ic && ia && c[i] < a[i] - 1e-9) {
      ++shorter;
      if (c[i] < a[i] - 0.25) ++shorter_far;
    }
  }
  auto pc = [n](long k) { return 100.0 * static_cast<double>(k) / static_cast<double>(n); };
  std::printf("sonar models: %zu ring readings on %zu poses, fired node by node\n", n, poses.size());
  std::printf("sonar models: ideal %.0f ns per reading, realistic %.0f ns: %.2fx (target <= 2x)\n",
              1e9 * t_ideal / static_cast<double>(n), 1e9 * t_real / static_cast<double>(n),
              t_real / t_ideal);
  std::printf("sonar models, paths alone: multipath turned %.2f %% of readings from silent to an echo and made %.2f %% "
              "longer; cross-talk made %.2f %% shorter (%.2f %% by more than 0.25 m)\n",
              pc(silence_to_echo), pc(longer), pc(shorter), pc(shorter_far));
}

}  // namespace

// Runs at least 600 simulated seconds and at least one wall second, then prints the rates.
int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : std::string(ROBUTER_WORLDS_DIR) + "/default.toml";
  auto w = load_world(path);
  if (!w.ok()) {
    std::fprintf(stderr, "%s\n", w.error().describe().c_str());
    return 1;
  }
  Scenario s(w.value());
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  const std::clock_t c0 = std::clock();
  long k = 0;
  double wall = 0.0;
  // At least 600 simulated seconds and at least 1 wall second.
  while (k < 60000 || wall < 1.0) {
    for (int i = 0; i < 1000; ++i) s.tick(k++);
    wall = std::chrono::duration<double>(clock::now() - t0).count();
  }
  const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  const double simulated = static_cast<double>(k) * 0.01;
  const double readings = static_cast<double>(s.sonar_reads + 2 * s.ptu_reads);
  std::printf("sim: world %s, robot step 10 ms, 24 ring sonars every 40 ms, pan-tilt pair every 30 ms\n",
              w.value().name.c_str());
  std::printf("sim: %.0f simulated s in %.3f wall s: %.0f simulated s per wall s\n", simulated, wall,
              simulated / wall);
  std::printf("sim: %.0f simulated s per CPU s (the wall figure drops when other jobs share the cores)\n",
              simulated / cpu);
  std::printf("sim: %.0f sonar readings and %.0f robot steps per wall s; robot travelled %.1f m\n",
              readings / wall, static_cast<double>(k) / wall, s.robot.travelled());
  compare_models(w.value(), s.visited);
  return 0;
}
