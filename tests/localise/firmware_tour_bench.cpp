// SPDX-License-Identifier: GPL-3.0-or-later
// Issue #18's acceptance through the whole firmware (make bench, tools/bench/81-localise-firmware.sh):
// the building floor's corridor loop driven by an operator's client (floor_tour.hpp), the
// simulator's odometry and sonar noise on, [localise] enabled on the place graph's walls. Prints
// the map pose's error (the localisation's) next to the odometry's over the tour, or, with
// `kidnap`, how long the map pose took to find the robot carried 3 m along its corridor.
//
//   robuter_localise_firmware_bench tour SECONDS SEED
//   robuter_localise_firmware_bench kidnap SECONDS SEED   (SECONDS after the carry at most)
// The kidnapping's place is seeded: carried at 60 + 41 (SEED - 1) s into the tour (the first lap's
// first two thirds: corridors, crossings, doors), back along the loop for an even SEED, on for an
// odd one; ROBUTER_TOUR_KIDNAP_AT=S carries it at S s instead (60: the first crossing).
// ROBUTER_TOUR_IDEAL_SONAR=1: the ring without noise (the odometry's stays); ROBUTER_TOUR_TRACE=1:
// the truth, the map pose's error and the localisation's report every second.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "tests/localise/floor_tour.hpp"

int main(int argc, char** argv) {
  if (argc != 4 || (std::string(argv[1]) != "tour" && std::string(argv[1]) != "kidnap")) {
    std::fprintf(stderr, "usage: %s tour|kidnap SECONDS SEED\n", argv[0]);
    return 2;
  }
  robuter::test::FloorTourSpec spec;
  spec.kidnap = std::string(argv[1]) == "kidnap";
  spec.seconds = std::atof(argv[2]);
  spec.seed = std::strtoull(argv[3], nullptr, 10);
  // The sonars: realistic (issue #19's model), or ROBUTER_TOUR_SONAR=ideal|stress|realistic
  // (ROBUTER_TOUR_IDEAL_SONAR, the older switch, is ideal).
  if (std::getenv("ROBUTER_TOUR_IDEAL_SONAR") != nullptr) spec.sonar_model = robuter::sim::SonarPreset::ideal;
  if (const char* name = std::getenv("ROBUTER_TOUR_SONAR")) {
    const auto model = robuter::sim::sonar_preset(name);
    if (!model) {
      std::fprintf(stderr, "ROBUTER_TOUR_SONAR=%s: expected %s\n", name, std::string(robuter::sim::sonar_preset_choices()).c_str());
      return 2;
    }
    spec.sonar_model = *model;
  }
  spec.trace = std::getenv("ROBUTER_TOUR_TRACE") != nullptr;
  spec.kidnap_at = 60.0 + 41.0 * static_cast<double>(spec.seed - 1);
  spec.kidnap_back = spec.seed % 2 == 0;
  if (const char* at = std::getenv("ROBUTER_TOUR_KIDNAP_AT")) spec.kidnap_at = std::atof(at);
  const robuter::test::FloorTourResult r = robuter::test::run_floor_tour(spec);
  if (!r.ok) return 1;
  const double deg = 180.0 / M_PI;
  if (spec.kidnap) {
    std::printf("kidnap seed %llu, %s sonars: carried 3 m %s at %.0f s from (%.1f, %.1f): found after %.1f s (limit %.0f s); "
                "protective stops %u, trips %u, worst activation %u us, scouts fired %u\n",
                static_cast<unsigned long long>(spec.seed), std::string(robuter::sim::sonar_preset_name(spec.sonar_model)).c_str(),
                spec.kidnap_back ? "back" : "on", r.kidnapped_at, r.kidnap_x, r.kidnap_y,
                r.found_after, spec.seconds, r.protective_stops, r.trips, r.run_us_max, r.scouts_fired);
    return 0;
  }
  std::printf("tour seed %llu, %s sonars: %.0f s, %.0f m driven; map pose p95 %.0f mm %.2f deg, worst %.0f mm %.2f deg; "
              "odometry p95 %.0f mm %.2f deg; protective stops %u, trips %u, localise worst activation %u us, scouts fired %u\n",
              static_cast<unsigned long long>(spec.seed), std::string(robuter::sim::sonar_preset_name(spec.sonar_model)).c_str(),
              spec.seconds, r.driven, 1000.0 * r.map_p95, r.map_heading_p95 * deg,
              1000.0 * r.map_worst, r.map_heading_worst * deg, 1000.0 * r.odometry_p95, r.odometry_heading_p95 * deg,
              r.protective_stops, r.trips, r.run_us_max, r.scouts_fired);
  return 0;
}
