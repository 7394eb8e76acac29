// SPDX-License-Identifier: GPL-3.0-or-later
// The topological map's parameters ([places]): the table (compiled once, not in every includer of the configuration).
#include "modules/places/places_params.hpp"

namespace robuter {

std::span<const param::Param<PlacesConfig>> places_params() {
  using P = param::Param<PlacesConfig>;
  static constexpr P kRows[] = {
      P::text("file", &PlacesConfig::file, "path", "place graph (\"robuter-places 1\", odometry frame), resolved against the configuration's folder; empty = none"),
      P::text("grids_dir", &PlacesConfig::grids_dir, "path", "folder of the place grids saved after each scan (seed 003's drawsec()), resolved like file; empty = none"),
      P::flag("cross_doors", &PlacesConfig::cross_doors, "XQ: at a narrow door the planner lends the robot to the door crossing (which lowers the detections in the door): off unless configured"),
      P::flag("load_grids", &PlacesConfig::load_grids, "at start-up, the grids_dir's saved grids are the planner's memory of the floor (docs/PLACES.md)"),
  };
  return kRows;
}

}  // namespace robuter
