// SPDX-License-Identifier: GPL-3.0-or-later
// One door crossing on the whole simulated firmware: a world with its start moved, AG until the
// passage finder ends, Ad until the crossing ends; contact, times and the end pose recorded.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "hal/sim/sonar_presets.hpp"
#include "kernel/config.hpp"
#include "picture/layout.hpp"

namespace robuter::test {

// How a run is set up.
struct CrossingSetup {
  std::string world;              // world file (door90, door100, gap70 …)
  double dx_m = 0.0;              // start moved along the world x axis (across the door), m
  double dy_m = 0.0;              // start moved along the world y axis (towards the door), m
  double dheading_deg = 0.0;      // start heading turned, degrees (counter-clockwise)
  std::uint64_t seed = 1;         // simulator seed
  sim::SonarPreset sonar_model = sim::SonarPreset::ideal;  // the simulator's sonar model
  bool odometry_noise = false;    // simulator odometry noise
  bool send_ad = true;            // send Ad once the passage finder has ended
  bool ad_even_if_gate_failed = false;  // send Ad although the passage finder failed
  std::int64_t unplug_after_ticks = -1;  // unplug the pan-tilt this long after Ad (−1: never)
  std::int64_t cancel_after_ticks = -1;  // send Af this long after Ad (−1: never)
  std::int64_t close_link_after_ticks = -1;  // the client goes away this long after Ad (−1: never)
  std::int64_t shutdown_after_ticks = -1;    // stop the firmware (kernel shutdown) this long after Ad (−1: never)
  int trace_every = 0;            // print pose and crossing decisions every this many ticks (0: never)
  bool trace_echoes = false;      // with trace_every: also every localised echo closer than 1.2 m
  std::string picture;            // write a picture of the run here (.png/.svg/.pdf; "" = none): trail, scan at Ad, scan at the end
  Config config;                  // firmware configuration
};

// What happened.
struct CrossingResult {
  bool started = false;           // the firmware ran
  std::string gate;               // the passage finder's end: "aligned" or "failed <reason>"
  std::string doors;              // the crossing's end: "crossed", "failed <reason>", "" when not sent
  bool contact = false;           // the bumper touched something at any tick
  double gate_s = 0.0;            // AG to the finder's end, simulated s
  double crossing_s = 0.0;        // Ad to the crossing's end, simulated s
  double total_s = 0.0;           // AG to the end, simulated s
  double end_x = 0.0, end_y = 0.0, end_heading_deg = 0.0;  // true pose at the end, m / degrees
  bool body_through = false;      // the whole body beyond the wall's far face (y > 4.05 m)
  bool stopped = false;           // wheel speeds zero at the end
  int mask_during = -1;           // emergency mask seen while crossing
  int mask_after = -1;            // emergency mask after the end
  std::string pan_tilt;            // the pan-tilt's state at the end: "scanning", "failed unit-lost" …
  std::string log;                // XD replies at the ends, for messages
  std::string picture_error;      // why the picture was not written ("" = written, or none asked)
  picture::Layout picture_layout; // what the picture laid out (title, legend, scale bar, labels)
};

CrossingResult run_crossing(const CrossingSetup& s);

// A start drawn from `seed`: lateral offset uniform in ±max_lateral_m, heading uniform in
// ±max_heading_deg (the same seed always gives the same start).
CrossingSetup seeded_start(const std::string& world, std::uint64_t seed, double max_lateral_m = 0.4,
                           double max_heading_deg = 20.0);

}  // namespace robuter::test
