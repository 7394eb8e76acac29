// SPDX-License-Identifier: GPL-3.0-or-later
// robuter-sim: command-line tools around the simulated Robuter (for now: `render`, pictures).
#include <CLI/CLI.hpp>

#include "cli/parse_or_usage.hpp"
#include "hal/sim/render.hpp"
#include "tools/robuter-sim/render_command.hpp"

// Why subcommands: room for more simulator tools beside `render`.
int main(int argc, char** argv) {
  using robuter::simtool::RenderRequest;
  CLI::App app{"robuter-sim — tools for the simulated Robuter"};
  app.require_subcommand(1);
  RenderRequest req;
  double pan_tilt = 0.0;
  CLI::App* render = app.add_subcommand("render", "draw a world with the robot at a pose, its sonar ring beams and pan-tilt rays");
  render->add_option("--world", req.world, "world file (.toml project format or seed-000 .env)")->required();
  render->add_option("--pose", req.pose, "robot pose X,Y,THETA_DEG (m, m, degrees); default: the world's start");
  render->add_flag("--ring", req.ring, "draw the 24 ring sonar beams with their ranges at that pose");
  CLI::Option* pt = render->add_option("--pan-tilt", pan_tilt, "draw the pan-tilt's two rays at this pan angle, degrees (rays at angle ± 90°)");
  render->add_option("-o,--output", req.output, "picture to write: .png, .svg or .pdf")->required();
  render->add_option("--scale", req.scale, "pixels per metre (default: the scale that makes the picture 1000 pixels wide)")->check(CLI::Range(5.0, 1000.0));
  render->add_option("--places", req.places, "a place graph (robuter-places 1, docs/PLACES.md) to draw over the world");
  render->add_option("--route", req.route, "with --places: draw the route FROM,TO between two places (names)");
  render->add_option("--place-grid", req.place_grids, "a place grid file (docs/PLACES.md, \"Place grids\") to draw at its place; repeatable");
  render->add_option("--title", req.title, "title (default: world, pose, date and what the sonars report)");
  render->add_option("--sonar-model", req.sonar_model, "the sonars' model: ideal (default), stress or realistic (docs/SIMULATOR.md); the ring is fired node by node");
  render->add_option("--seed", req.seed, "seed of the sonar model's random effects (default 1)");
  if (const auto status = robuter::cli::parse_or_usage(app, argc, argv)) return *status;
  if (pt->count() > 0) req.pan_tilt_deg = pan_tilt;
  const int status = robuter::simtool::run_render(req);
  robuter::sim::release_render_caches();  // LeakSanitizer: cairo's and fontconfig's caches
  return status;
}
