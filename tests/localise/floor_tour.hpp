// SPDX-License-Identifier: GPL-3.0-or-later
// The building floor's corridor loop driven through the whole firmware by an operator's client
// (AM lines steered by the true pose), [localise] enabled: the map pose's error against the truth.
#pragma once

#include <cstdint>

#include "hal/sim/sonar_presets.hpp"

namespace robuter::test {

// How the tour runs.
struct FloorTourSpec {
  double seconds = 60.0;          // robot time driven after the start, s
  std::uint64_t seed = 1;         // the simulator's noise
  sim::SonarPreset sonar_model = sim::SonarPreset::realistic;  // the sonars' model (the odometry's noise is always on)
  bool kidnap = false;            // carried 3 m along the loop, the firmware not told
  double kidnap_at = 60.0;        // s into the tour (the first second after it with a clear spot)
  bool kidnap_back = false;       // carried back along the loop, not on (on, where back is no clear spot)
  bool trace = false;             // print the truth, the error and the localisation every second
};

// What it measured (errors every second of the tour; kidnap: from the carry on).
struct FloorTourResult {
  bool ok = false;                    // the firmware started
  double driven = 0.0;                // m of the true path
  double map_p95 = 0.0;               // m, the map pose's position error, 95th percentile
  double map_heading_p95 = 0.0;       // rad
  double map_worst = 0.0;             // m
  double map_heading_worst = 0.0;     // rad
  double odometry_p95 = 0.0;          // m, the odometry's
  double odometry_heading_p95 = 0.0;  // rad
  double found_after = -1.0;          // kidnap: s of driving until the map pose was within 0.2 m and
                                      // 10° for 2 s running (-1: not found)
  std::uint32_t protective_stops = 0; // the envelope's
  std::uint32_t trips = 0;            // emergencies
  std::uint32_t run_us_max = 0;       // the localisation's longest activation, µs CPU
  std::uint32_t scouts_fired = 0;     // times a scout drew particles (a tracked tour: none)
  double kidnapped_at = -1.0;         // kidnap: s into the tour it happened (-1: no clear spot)
  double kidnap_x = 0.0;              // and where the robot was carried from, m
  double kidnap_y = 0.0;
};

FloorTourResult run_floor_tour(const FloorTourSpec& spec);

}  // namespace robuter::test
