// SPDX-License-Identifier: GPL-3.0-or-later
// The localisation module's parameters ([localise]).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/param.hpp"

namespace robuter {

// Localisation on the robot's map (modules/localise, docs/LOCALISATION.md).
struct LocaliseConfig {
  bool enabled = false;               // run the particle filter on the map (planner.map_file or the place graph's walls)
  std::uint32_t min_particles = 200;  // KLD-sampling keeps at least this many
  std::uint32_t max_particles = 2000; // and at most this many (every buffer is this size, from start-up)
  std::uint32_t particles_per_run = 200;  // particles weighed per activation (the bound on its work: docs/LOCALISATION.md)
  std::uint32_t traces_per_run = 64;      // and of them, at most this many with the map's promises traced
  std::uint32_t initial_sigma_mm = 100;   // spread of the start pose (the odometry's, a state file's, XA's), mm
  std::uint32_t initial_sigma_deg = 5;    // and of its heading, degrees
  bool report_corrected = false;      // BO, BV and the XS stream report the map pose instead of the odometry's
  std::string state_file;             // the last estimate, kept across restarts (written off the periodic path); empty = none
  std::uint64_t seed = 1;             // the filter's random draws (a run is reproducible)
};

// [localise]: each key, its unit, range and doc (the default is the field's initialiser).
std::span<const param::Param<LocaliseConfig>> localise_params();

}  // namespace robuter
