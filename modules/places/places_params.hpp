// SPDX-License-Identifier: GPL-3.0-or-later
// The topological map's parameters ([places]).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/param.hpp"

namespace robuter {

// [places]: seed 003's topological map (docs/PLACES.md).
struct PlacesConfig {
  std::string file;   // place graph ("robuter-places 1", odometry frame), resolved against the configuration's folder; empty = none
  int file_line = 0;  // line of places.file in the configuration (0: not written)
  std::string grids_dir;  // folder of the place grids saved after each scan (seed 003's drawsec()), resolved like file; empty = none
  bool load_grids = false;   // at start-up, the grids_dir's saved grids are the planner's memory of the floor (docs/PLACES.md)
  bool cross_doors = false;  // XQ: at a narrow door the planner lends the robot to the door crossing (which lowers the detections in the door): off unless configured
};

// [places]: each key, its unit, range and doc (the default is the field's initialiser).
std::span<const param::Param<PlacesConfig>> places_params();

}  // namespace robuter
