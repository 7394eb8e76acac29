// SPDX-License-Identifier: GPL-3.0-or-later
// Reaction-time trials on the whole simulated firmware, shared by the test and tools/bench/safety.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "kernel/config.hpp"
#include "modules/topics.hpp"

namespace robuter::test::safety_sim {

// One trial: the robot drives at an obstacle (approach) or an obstacle appears in its path
// (teleport: the moving robot is placed in front of a box, inside the safety distance).
struct ReactionTrial {
  std::uint64_t seed = 1;  // draws the trial (and the sonar noise, off here)
  int left = 30;           // AM wheel speeds, cm/s
  int right = 30;
  double distance = 1.0;   // front face to the box's near face: at the start (approach) or after the teleport, m
  double lateral = 0.0;    // box centre's offset across the path, m
  double box_angle = 0.0;  // box rotation, degrees
  double box_size = 0.6;   // box side, m
  bool teleport = false;   // true: the obstacle appears inside the safety distance
};

// What a trial measured, in ticks of the kernel (10 ms).
struct ReactionResult {
  bool ran = false;                // the firmware started and the trial completed
  std::string error;               // why not
  bool tripped = false;            // the emergency stopped the robot
  EmergencyCause cause = EmergencyCause::none;
  int sensor = 0;                  // the watch-dog sensor whose reading was the first under the limit
  int range_mm = 0;                // that reading, mm
  std::uint32_t safety_mm = 0;     // the safety distance in force, mm
  std::uint64_t appear_tick = 0;   // first tick the body was within the safety distance (teleport: the placement)
  std::uint64_t visible_tick = 0;  // first tick a watch-dog sensor's ideal reading (no noise) was under the limit
  std::uint64_t read_tick = 0;     // UltrasonicRanges.read_tick of that reading
  std::uint64_t seen_tick = 0;     // first read at or after appear_tick of an echo from the box, any sensor
  std::uint64_t stop_tick = 0;     // tick in which SimDrive::commanded became zero
  bool contact = false;            // the bumper was pressed at some point
  double clearance_at_rest_mm = 0; // true body-to-obstacle distance once at rest, mm

  std::int64_t reaction_ticks() const { return static_cast<std::int64_t>(stop_tick) - static_cast<std::int64_t>(read_tick); }
  std::int64_t detection_ticks() const { return static_cast<std::int64_t>(read_tick) - static_cast<std::int64_t>(appear_tick); }
  // Body within the safety distance to a reading that sees the box (issue #13's ring criterion:
  // the envelope judges every echo against the body, whatever its range).
  std::int64_t sighting_ticks() const { return static_cast<std::int64_t>(seen_tick) - static_cast<std::int64_t>(appear_tick); }
  // The ring's own part: from when a watch-dog sensor could read it under the limit to the read.
  std::int64_t ring_ticks() const { return static_cast<std::int64_t>(read_tick) - static_cast<std::int64_t>(visible_tick); }
};

// A trial drawn from `seed`: speeds 10…80 cm/s (straight or a soft curve), box size, angle,
// offset, and a distance outside (approach) or inside (teleport) the safety distance.
ReactionTrial random_trial(std::uint64_t seed, bool teleport);

// Runs one trial on a fresh firmware in a 16 × 8 m arena, configured by `cfg` (core_config()
// by default).
ReactionResult run_trial(const ReactionTrial& t);
ReactionResult run_trial(const ReactionTrial& t, const Config& cfg);

// The ring as the firmware ran before the watch schedule: the seed's order while moving and the
// `us` row at the seed's period 4 (offset 2), on top of `cfg`. For before/after figures.
Config seed_ring_config(Config cfg);

// A percentile of a sorted sample (nearest rank); 0 for an empty one.
std::int64_t percentile(const std::vector<std::int64_t>& sorted, double p);

}  // namespace robuter::test::safety_sim
