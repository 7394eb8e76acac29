// SPDX-License-Identifier: GPL-3.0-or-later
// A map's distance field: the localisation's likelihood field and the safety core's structure test.
#pragma once

#include "modules/localise/lib/distance_field.hpp"
#include "modules/planner/lib/occupancy_map.hpp"

namespace robuter::localise {

// Each cell's distance to the nearest occupied cell of `map`, capped at `reach` m (allocates: at
// start-up only).
loc::DistanceField distance_field(const plan::OccupancyMap& map, double reach);

}  // namespace robuter::localise
