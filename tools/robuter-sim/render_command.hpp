// robuter-sim render: options and the picture of a world with the robot and its sonars at one pose.
#pragma once

#include <optional>
#include <string>

namespace robuter::simtool {

// What `robuter-sim render` was asked for.
struct RenderRequest {
  std::string world;                   // world file (.toml or seed-000 .env)
  std::string pose;                    // "X,Y,THETA_DEG" (m, m, degrees); empty = the world's start
  bool ring = false;                   // draw the 24 ring beams with their ranges at the pose
  std::optional<double> pan_tilt_deg;  // draw the pan-tilt pair at this pan angle, degrees
  std::string output;                  // .png or .svg
  double scale = 60.0;                 // pixels (points) per metre
  std::string title;                   // caption; empty = world name and pose
};

// Renders the request; 0 on success, else prints why on stderr and returns 1.
int run_render(const RenderRequest& r);

}  // namespace robuter::simtool
