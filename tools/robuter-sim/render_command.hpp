// SPDX-License-Identifier: GPL-3.0-or-later
// robuter-sim render: options and the picture of a world with the robot and its sonars at one pose.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace robuter::simtool {

// What `robuter-sim render` was asked for.
struct RenderRequest {
  std::string world;                   // world file (.toml or seed-000 .env)
  std::string pose;                    // "X,Y,THETA_DEG" (m, m, degrees); empty = the world's start
  bool ring = false;                   // draw the 24 ring beams with their ranges at the pose
  std::optional<double> pan_tilt_deg;  // draw the pan-tilt pair at this pan angle, degrees
  std::string output;                  // .png, .svg or .pdf
  double scale = 0.0;                  // pixels (points) per metre; 0 = a 1000 px wide picture
  std::string places;                  // place graph file to draw over the world; empty = none
  std::string route;                   // "FROM,TO" place names: the route to draw (needs places)
  std::vector<std::string> place_grids;  // place grid files (docs/PLACES.md) to draw at their places
  std::string title;                   // title; empty = world, pose, date and the sonars' report
  std::string sonar_model = "ideal";   // the sonars' model (docs/SIMULATOR.md): ideal, stress, realistic
  std::uint64_t seed = 1;              // seed of the model's random effects
};

// Renders the request; 0 on success, else prints why on stderr and returns 1.
int run_render(const RenderRequest& r);

}  // namespace robuter::simtool
