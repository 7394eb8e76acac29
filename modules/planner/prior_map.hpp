// SPDX-License-Identifier: GPL-3.0-or-later
// The firmware planner's a-priori map ([planner] map_file): read and checked once at start-up.
#pragma once

#include <string>

#include "kernel/config.hpp"
#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/planner/lib/result.hpp"

namespace robuter::planner {

// A map file made ready for the planner.
struct PriorMap {
  plan::OccupancyMap map;  // the file's geometry and counts, with [planner] hit_threshold and initial_count
  std::string note;        // one line for --check-config: file, cells, resolution, origin, obstacles
};

// Why: the file's header is the map's geometry. Decided: a [planner] geometry key
// (map_origin_x_mm, map_origin_y_mm, map_width_mm, map_height_mm, cell_mm) that is also written
// must agree with it, keys left out are taken from it — so a configuration never silently
// plans on a map other than the one it names. On success `p`'s geometry is the file's (the
// link's XG check and the module see the same map). The file's counts are kept as prior
// evidence (hits); its cells must keep their state under [planner] hit_threshold. Every failure
// is one "FILE:LINE: message" and leaves `p` unchanged.
plan::Result<PriorMap> load_prior_map(PlannerModuleConfig& p, const std::string& config_file);

}  // namespace robuter::planner
