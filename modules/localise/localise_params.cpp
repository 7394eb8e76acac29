// SPDX-License-Identifier: GPL-3.0-or-later
// The localisation module's parameters ([localise]): the table (compiled once, not in every includer of the configuration).
#include "modules/localise/localise_params.hpp"

namespace robuter {

std::span<const param::Param<LocaliseConfig>> localise_params() {
  using P = param::Param<LocaliseConfig>;
  static constexpr P kRows[] = {
      P::flag("enabled", &LocaliseConfig::enabled, "run the particle filter on the map (planner.map_file or the place graph's walls)"),
      P::integer("min_particles", &LocaliseConfig::min_particles, "integer", 10, 2'000, "KLD-sampling keeps at least this many"),
      P::integer("max_particles", &LocaliseConfig::max_particles, "integer", 10, 2'000, "and at most this many (every buffer is this size, from start-up)"),
      P::integer("particles_per_run", &LocaliseConfig::particles_per_run, "integer", 10, 300, "particles weighed per activation (the bound on its work: docs/LOCALISATION.md)"),
      P::integer("traces_per_run", &LocaliseConfig::traces_per_run, "integer", 10, 80, "and of them, at most this many with the map's promises traced"),
      P::integer("initial_sigma_mm", &LocaliseConfig::initial_sigma_mm, "integer", 0, 100'000, "spread of the start pose (the odometry's, a state file's, XA's), mm"),
      P::integer("initial_sigma_deg", &LocaliseConfig::initial_sigma_deg, "integer", 0, 180, "and of its heading, degrees"),
      P::flag("report_corrected", &LocaliseConfig::report_corrected, "BO, BV and the XS stream report the map pose instead of the odometry's"),
      P::text("state_file", &LocaliseConfig::state_file, "path", "the last estimate, kept across restarts (written off the periodic path); empty = none"),
      P::integer("seed", &LocaliseConfig::seed, "integer", 0, param::kU32, "the filter's random draws (a run is reproducible)"),
  };
  return kRows;
}

}  // namespace robuter
