// SPDX-License-Identifier: GPL-3.0-or-later
// robuter-plan: plans once from the thesis' files (-p / -a) or answers MovingAI scenario files.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "cli/parse_or_usage.hpp"
#include "modules/planner/lib/cspace.hpp"
#include "modules/planner/lib/grid_search.hpp"
#include "modules/planner/lib/map_file.hpp"
#include "modules/planner/lib/movingai.hpp"
#include "modules/planner/lib/planner.hpp"
#include "modules/planner/lib/text_render.hpp"
#include "modules/planner/lib/thesis_files.hpp"
#include "picture/page.hpp"
#include "tools/robuter-plan/picture.hpp"
#include "tools/robuter-plan/world_map.hpp"

namespace {

using namespace robuter::plan;

// Command-line choices.
struct Options {
  std::string params;                     // -p: thesis parameter file
  std::string environment;                // -a: thesis environment file
  std::string saved;                      // -s: saved map (robuter-map format)
  std::string world;                      // -w: the project's world file (.toml) or a seed 000 .env
  std::vector<double> goal;               // --goal X Y (m): overrides the file's goal
  double radius = 0.78;                   // m, disc radius when no -p gives one (the firmware's default)
  std::string picture;                    // -o: picture to write (PNG, or PDF)
  std::string save_map;                   // --save-map: write the map used
  std::vector<std::string> movingai;      // --movingai MAP SCEN
  std::string mode = "optimal";           // optimal | bfs
  std::string footprint = "disc";         // disc | rectangle
  std::string motion = "aligned";         // aligned | holonomic
  double width_m = 15.0;                  // m, map size along x (the thesis: 15 m)
  double height_m = 15.0;                 // m, map size along y
  double resolution = 0.05;               // m per cell
  int slices = 16;                        // heading slices over a half turn
  double unknown_cost = 1.0;              // multiplier on unknown cells
  double rotation_cost = 0.30;            // m per rad turned
  bool text = false;                      // print seed 003's text picture around the start
  bool thesis_log = false;                // print seed 000's gt.log: the expanded map with O, D, X
  bool waypoints = false;                 // print the path
};

// Why: print an error the same way everywhere and give the shell a failure code.
int fail(const Error& e) {
  std::fprintf(stderr, "robuter-plan: %s\n", e.text().c_str());
  return 1;
}

// Why: --movingai: one line per scenario, "index length" or "index none".
int run_movingai(const Options& o) {
  auto map = load_movingai_map(o.movingai[0]);
  if (!map) return fail(map.error());
  auto scen = load_movingai_scen(o.movingai[1]);
  if (!scen) return fail(scen.error());
  PassGrid grid;
  pass_grid_from_map(*map, grid);
  GridSearch search(grid.width, grid.height);
  const SearchMode mode = o.mode == "bfs" ? SearchMode::Bfs : SearchMode::Optimal;
  for (std::size_t i = 0; i < scen->size(); ++i) {
    const Scenario& s = (*scen)[i];
    const PlanResult r = search.find(grid, s.start, s.goal, mode);
    if (r.found()) std::printf("%zu %.6f\n", i, r.length);
    else std::printf("%zu none\n", i);
  }
  return 0;
}

// Why: -p / -a (or -s, or -w): the thesis' single plan, with a picture. Every input is read
// before anything is written, so a bad file leaves no picture and no saved map behind.
int run_thesis(const Options& o) {
  std::optional<ThesisParameters> params;
  if (!o.params.empty()) {
    auto loaded = load_parameters(o.params);
    if (!loaded) return fail(loaded.error());
    params = *loaded;
  }
  OccupancyMap map;
  std::optional<Pose2> world_start;
  std::optional<Point2> world_goal;
  if (!o.world.empty()) {
    auto loaded = tool::load_world_map(o.world, o.resolution);
    if (!loaded) return fail(loaded.error());
    map = std::move(loaded->map);
    world_start = loaded->start;
    world_goal = loaded->goal;
  } else if (!o.saved.empty()) {
    auto loaded = load_map(o.saved);
    if (!loaded) return fail(loaded.error());
    map = std::move(*loaded);
  } else {
    const double cols = std::ceil(o.width_m / o.resolution - 1e-9);
    const double rows = std::ceil(o.height_m / o.resolution - 1e-9);
    if (cols * rows > 16e6) return fail(Error{"", 0, "map too large: more than 16 million cells"});
    const MapGeometry g{static_cast<int>(cols), static_cast<int>(rows), o.resolution, {}};
    map = OccupancyMap(g);
    if (!o.environment.empty()) {
      auto env = load_environment(o.environment);
      if (!env) return fail(env.error());
      rasterise_polygons(map, *env);
    }
  }
  if (!params && (!world_start || (!world_goal && o.goal.empty())))
    return fail(Error{o.world, 0, "the world has no [start] and [goal]: give them with -p PARAMS"});
  const Pose2 start = params ? Pose2{params->start.x, params->start.y, params->heading_deg * kPi / 180.0}
                             : *world_start;
  Point2 goal_point = params ? params->goal : *world_goal;
  if (o.goal.size() == 2) goal_point = Point2{o.goal[0], o.goal[1]};
  if (!o.save_map.empty()) {
    if (auto st = save_map(map, o.save_map); !st) return fail(st.error());
  }
  PlannerConfig cfg;
  cfg.footprint = o.footprint == "rectangle" ? FootprintKind::Rectangle : FootprintKind::Disc;
  cfg.radius = params ? params->radius : o.radius;
  cfg.heading_slices = o.slices;
  cfg.motion = o.motion == "holonomic" ? MotionModel::Holonomic : MotionModel::Aligned;
  cfg.rotation_cost = o.rotation_cost;
  cfg.mode = o.mode == "bfs" ? SearchMode::Bfs : SearchMode::Optimal;
  cfg.unknown_cost = o.unknown_cost;
  cfg.incremental = false;
  Planner planner(cfg);
  planner.set_map(map);
  const PlanResult r = planner.plan(start, goal_point);
  const double res = map.resolution();
  if (o.text) {
    std::fputs(render_around(map, map.cell_of({start.x, start.y}), 30).c_str(), stdout);
  }
  if (o.thesis_log) {
    const Cell s = map.cell_of({start.x, start.y});
    // The thesis's robot is a disc (its expansion has one slice); a rectangle shows its slice 0.
    std::fputs(render_thesis_log(planner.expanded(0), s, map.cell_of(goal_point)).c_str(), stdout);
  }
  if (r.found()) {
    std::printf("path found: length %.3f m, cost %.3f, %zu waypoints, %u nodes expanded\n",
                r.length * res, r.cost * res, planner.waypoints().size(), r.expanded);
  } else {
    std::printf("no path: %s (%u nodes expanded)\n", std::string(to_string(r.status)).c_str(), r.expanded);
  }
  if (o.waypoints)
    for (const Waypoint& w : planner.waypoints())
      std::printf("%.3f %.3f %.1f\n", w.pose.x, w.pose.y, w.pose.heading * 180.0 / kPi);
  if (!o.picture.empty()) {
    if (auto st = tool::write_picture(planner, start, goal_point, o.picture, &r); !st) return fail(st.error());
  }
  return r.found() ? 0 : 2;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"robuter-plan: grid path planning (thesis files, MovingAI benchmarks)"};
  app.add_option("-p,--params", o.params, "thesis parameter file (radius, speed, heading, start, goal)");
  auto* env = app.add_option("-a,--environment", o.environment, "thesis environment file (obstacle polygons, m)");
  auto* saved = app.add_option("-s,--saved", o.saved, "saved map (robuter-map format) instead of -a");
  auto* world = app.add_option("-w,--world", o.world,
                               "the project's world file (.toml; .env as seed 000) instead of -a/-s; "
                               "start and goal from it unless -p gives them");
  env->excludes(saved);
  world->excludes(env);
  world->excludes(saved);
  app.add_option("--goal", o.goal, "goal X Y, m, instead of the file's")->expected(2);
  app.add_option("--radius", o.radius, "disc radius, m, when no -p gives one (default 0.78)")
      ->check(CLI::PositiveNumber);
  app.add_option("-o,--output", o.picture, "write a picture of the plan (PNG; PDF for a .pdf file): map, path, goal, outcome, axes, scale bar, legend");
  app.add_option("--save-map", o.save_map, "write the map used (robuter-map format)");
  app.add_option("--movingai", o.movingai, "answer a MovingAI .map and its .scen")->expected(2);
  app.add_option("--mode", o.mode, "search: optimal (A*, octile) or bfs (the thesis)")
      ->check(CLI::IsMember({"optimal", "bfs"}));
  app.add_option("--footprint", o.footprint, "disc (the parameter file's radius) or rectangle (Robuter)")
      ->check(CLI::IsMember({"disc", "rectangle"}));
  app.add_option("--motion", o.motion, "rectangle moves: aligned (differential drive) or holonomic")
      ->check(CLI::IsMember({"aligned", "holonomic"}));
  app.add_option("--width", o.width_m, "map width, m")->check(CLI::PositiveNumber);
  app.add_option("--height", o.height_m, "map height, m")->check(CLI::PositiveNumber);
  app.add_option("--resolution", o.resolution, "cell size, m")->check(CLI::PositiveNumber);
  app.add_option("--slices", o.slices, "heading slices over a half turn")->check(CLI::Range(1, 256));
  app.add_option("--unknown-cost", o.unknown_cost, "cost multiplier of unknown cells (>= 1)")->check(CLI::Range(1.0, 1e6));
  app.add_option("--rotation-cost", o.rotation_cost, "m of path per rad turned in place")->check(CLI::NonNegativeNumber);
  app.add_flag("--text", o.text, "print the map around the start in seed 003's characters");
  app.add_flag("--thesis-log", o.thesis_log,
               "print the whole expanded map as seed 000's gt.log: O start (M on an obstacle), D goal, X obstacle (a rectangle: slice 0)");
  app.add_flag("--waypoints", o.waypoints, "print the path: x y (m) heading (degrees)");
  // Usage errors keep CLI11's own codes (105..114): 2 is "no path" here, 1 a broken input file.
  if (const auto status = robuter::cli::parse_or_usage(app, argc, argv, robuter::cli::UsageStatus::cli11)) return *status;
  if (!o.movingai.empty()) return run_movingai(o);
  if (o.params.empty() && o.world.empty()) {
    std::fprintf(stderr, "robuter-plan: give -p PARAMS [-a ENVIRONMENT | -s SAVED], -w WORLD, or --movingai MAP SCEN\n");
    return 1;
  }
  const int status = run_thesis(o);
  if (!o.picture.empty()) robuter::picture::release_caches();  // the picture's fonts: LeakSanitizer
  return status;
}
