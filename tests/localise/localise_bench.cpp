// SPDX-License-Identifier: GPL-3.0-or-later
// The filter's figures on the simulated lab (tools/bench/80-localise.sh): error against odometry's,
// recovery times, and each step's CPU time.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "tests/localise/lab_tour.hpp"

using namespace robuter::loc;

namespace {

void print_steps(const char* what, const std::vector<test::TourSample>& samples) {
  std::vector<double> cpu;
  for (const auto& t : samples) cpu.push_back(t.step_cpu * 1e3);
  std::printf("  %s: %zu steps, step CPU p50 %.2f ms, p99 %.2f ms, worst %.2f ms\n", what, cpu.size(),
              test::quantile(cpu, 0.5), test::quantile(cpu, 0.99), test::quantile(cpu, 1.0));
}

// One tour's line: the filter's error beside the odometry's.
void print_tour(int seed, const std::vector<test::TourSample>& tour) {
  const double deg = 180.0 / std::numbers::pi;
  std::vector<double> fe, fh, oe, oh;
  for (const auto& t : tour) {
    fe.push_back(t.filter_error);
    fh.push_back(t.filter_heading * deg);
    oe.push_back(t.odometry_error);
    oh.push_back(t.odometry_heading * deg);
  }
  std::printf("seed %d: %.0f s; filter p95 %.0f mm %.2f deg, worst %.0f mm %.2f deg; odometry p95 %.0f mm %.1f deg\n",
              seed, tour.empty() ? 0.0 : tour.back().time, 1e3 * test::quantile(fe, 0.95), test::quantile(fh, 0.95),
              1e3 * test::quantile(fe, 1.0), test::quantile(fh, 1.0), 1e3 * test::quantile(oe, 0.95),
              test::quantile(oh, 0.95));
}

}  // namespace

int main(int argc, char** argv) {
  const int seeds = argc > 1 ? std::atoi(argv[1]) : 10;
  const auto lab = test::load_lab("default.toml");
  std::printf("localise: worlds/default.toml, %d seeds, odometry and sonar noise on\n", seeds);
  int kidnap_found = 0, global_found = 0;
  for (int seed = 1; seed <= seeds; ++seed) {
    auto spec = test::lab_loop(static_cast<std::uint64_t>(seed));
    spec.laps = 10;  // about 9 minutes of driving
    const auto tour = test::run_tour(lab, spec);
    print_tour(seed, tour);
    if (seed == 1) print_steps("tracking", tour);
    auto k = test::lab_loop(static_cast<std::uint64_t>(seed));
    k.laps = 3;
    k.kidnap_after = 20.0;
    k.kidnap_to_waypoint = 5;
    const auto kt = test::run_tour(lab, k);
    const double at = test::found_after(kt, 20.0);
    const double found = at < 0.0 ? -1.0 : at - 20.0;
    if (found >= 0.0 && found <= 30.0) ++kidnap_found;
    auto g = test::lab_loop(static_cast<std::uint64_t>(seed));
    g.laps = 2;
    g.global_start = true;
    const auto gt = test::run_tour(lab, g);
    const double gfound = test::found_after(gt);
    if (gfound >= 0.0 && gfound <= 60.0) ++global_found;
    std::printf("  kidnapped (carried 3+ m at 20 s): found after %.1f s; global start: found after %.1f s\n", found, gfound);
    if (seed == 1) {
      print_steps("global start", gt);
      g.slice = 300;  // the same run weighed 300 particles per activation
      print_steps("global start, 300 particles per part (the costliest part)", test::run_tour(lab, g));
    }
  }
  std::printf("kidnappings found within 30 s: %d of %d; global starts within 60 s: %d of %d\n", kidnap_found,
              seeds, global_found, seeds);

  // The building floor's corridors: long, alike, their doors the only landmarks along them.
  const auto floor = test::load_lab("building_floor.toml");
  const int laps = argc > 2 ? std::atoi(argv[2]) : 3;
  std::printf("localise: worlds/building_floor.toml corridors, %d laps, seeds 1-%d, the simulator's odometry noise\n", laps, std::min(seeds, 3));
  for (int seed = 1; seed <= std::min(seeds, 3); ++seed) {
    auto spec = test::floor_loop(static_cast<std::uint64_t>(seed));
    spec.laps = laps;
    test::use_simulator_odometry_noise(spec);
    const auto tour = test::run_tour(floor, spec);
    print_tour(seed, tour);
    if (seed == 1) print_steps("floor tracking", tour);
    // Where the error is: the filter's mean error per 5 m x 5 m square the robot drove through, the worst five.
    std::vector<std::pair<double, std::pair<int, int>>> squares;
    for (const auto& t : tour) {
      const std::pair<int, int> sq{static_cast<int>(t.truth.x() / 5.0), static_cast<int>(t.truth.y() / 5.0)};
      auto it = std::find_if(squares.begin(), squares.end(), [&](const auto& e) { return e.second == sq; });
      if (it == squares.end()) squares.push_back({t.filter_error, sq});
      else it->first = std::max(it->first, t.filter_error);
    }
    std::sort(squares.begin(), squares.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::printf("  worst squares (5 m, by their worst error):");
    for (std::size_t i = 0; i < std::min<std::size_t>(5, squares.size()); ++i)
      std::printf(" (%d-%d, %d-%d m) %.0f mm;", squares[i].second.first * 5, squares[i].second.first * 5 + 5,
                  squares[i].second.second * 5, squares[i].second.second * 5 + 5, squares[i].first * 1e3);
    std::printf("\n");
  }
  return 0;
}
