// SPDX-License-Identifier: GPL-3.0-or-later
// The topological map's parameters ([places]): the table (compiled once, not in every includer of the configuration).
#include "modules/places/places_params.hpp"

namespace robuter {

namespace {
constexpr param::Param<PlacesConfig> kPlacesParams[] = {
    {"file", &PlacesConfig::file, "path", 0, 0, "",
     "place graph (\"robuter-places 1\", odometry frame), resolved against the configuration's folder; empty = none"},
    {"grids_dir", &PlacesConfig::grids_dir, "path", 0, 0, "",
     "folder of the place grids saved after each scan (seed 003's drawsec()), resolved like file; empty = none"},
    {"cross_doors", &PlacesConfig::cross_doors, "bool", 0, 0, "",
     "XQ: at a narrow door the planner lends the robot to the door crossing (which lowers the detections in the door): off unless configured"},
    {"load_grids", &PlacesConfig::load_grids, "bool", 0, 0, "",
     "at start-up, the grids_dir's saved grids are the planner's memory of the floor (docs/PLACES.md)"},
};
}  // namespace

std::span<const param::Param<PlacesConfig>> places_params() { return kPlacesParams; }

}  // namespace robuter
