// SPDX-License-Identifier: GPL-3.0-or-later
// robuter-sim render: load the world, place the robot, measure the sonars there, draw.
#include "tools/robuter-sim/render_command.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <optional>
#include <span>

#include "hal/sim/render.hpp"
#include "hal/sim/sonar_layout.hpp"
#include "hal/sim/sonar_presets.hpp"
#include "hal/sim/world_io.hpp"
#include "modules/places/place_graph_file.hpp"
#include "modules/places/place_grid.hpp"
#include "modules/places/place_picture.hpp"
#include "picture/page.hpp"

namespace robuter::simtool {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;  // radians per degree

// Why strict: a mistyped pose must not silently draw the robot somewhere else.
bool parse_pose(const std::string& text, sim::Pose& out) {
  double v[3];
  const char* p = text.c_str();
  for (int i = 0; i < 3; ++i) {
    char* end = nullptr;
    v[i] = std::strtod(p, &end);
    if (end == p || !std::isfinite(v[i])) return false;
    p = end;
    if (i < 2) {
      if (*p != ',') return false;
      ++p;
    }
  }
  if (*p != '\0') return false;
  out = {v[0], v[1], v[2] * kDeg};
  return true;
}

// What, when and outcome: the world and pose, the date, and what the sonars drawn report.
std::string default_title(const std::string& world, const sim::Pose& pose, const sim::Scene& scene) {
  char t[320];
  int n = std::snprintf(t, sizeof t, "robuter-sim render, %s, robot at (%.2f m, %.2f m, %.0f deg), %s", world.c_str(), pose.x,
                        pose.y, pose.theta / kDeg, picture::utc_now().c_str());
  const auto report = [&](const std::vector<sim::SonarBeam>& beams, const char* what) {
    if (beams.empty() || n < 0 || n >= static_cast<int>(sizeof t)) return;
    int echoes = 0;
    const sim::SonarBeam* nearest = nullptr;
    for (const auto& b : beams) {
      if (b.range <= 0.0) continue;
      ++echoes;
      if (nearest == nullptr || b.range < nearest->range) nearest = &b;
    }
    n += std::snprintf(t + n, sizeof t - static_cast<std::size_t>(n), "; %s: %d of %zu echo", what, echoes, beams.size());
    if (nearest != nullptr && n < static_cast<int>(sizeof t))
      n += std::snprintf(t + n, sizeof t - static_cast<std::size_t>(n), ", nearest %.2f m", nearest->range);
  };
  report(scene.beams, "ring");
  report(scene.pan_tilt, "pan-tilt");
  return t;
}

// Why one place: every refusal looks the same and gives the shell status 1.
int fail(const std::string& why) {
  std::fprintf(stderr, "robuter-sim: %s\n", why.c_str());
  return 1;
}
}  // namespace

// Why measure here: the picture shows what the sonars would report at that pose, with the same
// models the simulated firmware uses (ring: 33 ms at 300 m/s; pan-tilt: 15 ms at 335 m/s and
// the seed's calibration error).
int run_render(const RenderRequest& r) {
  if (!sim::picture_format_ok(r.output)) return fail("-o " + r.output + ": expected a .png, .svg or .pdf file");
  const sim::RobotGeometry geometry;
  auto loaded = sim::load_world(r.world, geometry);
  if (!loaded) return fail(loaded.error().describe());
  sim::World world = std::move(loaded).value();
  sim::Pose pose = world.start.value_or(sim::Pose{});
  if (!r.pose.empty()) {
    if (!parse_pose(r.pose, pose)) return fail("--pose '" + r.pose + "': expected X,Y,THETA_DEG (m, m, degrees)");
    world.start = pose;  // checked like a start pose: the body must be clear of every obstacle
    if (auto ok = sim::check_world_poses(world, geometry); !ok)
      return fail("--pose " + r.pose + ": " + ok.error().message);
  }

  const auto preset = sim::sonar_preset(r.sonar_model);
  if (!preset) return fail("--sonar-model '" + r.sonar_model + "': expected " + std::string(sim::sonar_preset_choices()));
  sim::Rng rng(r.seed);

  sim::Scene scene;
  scene.world = &world;
  scene.geometry = geometry;
  scene.robot = pose;
  if (r.ring) {
    const sim::RingLayout layout = sim::default_ring_layout();
    sim::SonarParams params = sim::default_ring_params();
    sim::apply_sonar_preset(*preset, params);
    sim::SonarModel model(world, params);
    std::array<double, sim::kRingSensors> ranges{};
    // Node by node, as the ring fires: node-mates may hear each other (cross-talk).
    for (std::size_t n = 0; n < layout.size(); n += 4) {
      model.measure_firing(pose, std::span<const sim::SonarMount>(layout).subspan(n, 4), std::span<double>(ranges).subspan(n, 4), &rng);
    }
    scene.beams = sim::ring_beams(pose, layout, ranges, params);
  }
  if (r.pan_tilt_deg) {
    // Seed ptu.c: at pan angle a, one sonar looks along a + 90° (robot frame), the other a − 90°.
    sim::SonarParams params = sim::default_pan_tilt_params();
    sim::apply_sonar_preset(*preset, params);
    sim::SonarModel model(world, params);
    const sim::PanTiltMount mount;
    const double direction = (*r.pan_tilt_deg + 90.0) * kDeg;
    const sim::PanTiltReading reading = sim::measure_pan_tilt(model, pose, mount, direction, &rng);
    scene.pan_tilt = sim::pan_tilt_beams(pose, mount, direction, reading, params);
  }
  std::optional<places::PlaceGraph> graph;
  places::PlaceRoute route;
  if (!r.route.empty() && r.places.empty()) return fail("--route needs --places (the place graph it runs over)");
  if (!r.places.empty()) {
    auto g = places::load_place_graph(r.places);
    if (!g) return fail(g.error().describe());
    graph = std::move(g).value();
    if (!r.route.empty()) {
      const auto comma = r.route.find(',');
      const auto from = comma == std::string::npos ? std::nullopt : graph->find(r.route.substr(0, comma));
      const auto to = comma == std::string::npos ? std::nullopt : graph->find(r.route.substr(comma + 1));
      if (!from || !to) return fail("--route '" + r.route + "': expected FROM,TO, two place names of " + r.places);
      route = places::shortest_route(*graph, *from, *to);
      if (!route.found) return fail("--route '" + r.route + "': no chain of doors joins these places");
    }
    scene.overlay = places::place_graph_overlay(*graph, r.route.empty() ? nullptr : &route);
    scene.keys = places::place_graph_keys(!r.route.empty());
  }
  std::vector<places::PlaceGrid> grids;
  for (const std::string& f : r.place_grids) {
    auto g = places::load_place_grid(f);
    if (!g) return fail(g.error().text());
    grids.push_back(std::move(g).value());
  }
  if (!grids.empty()) {
    scene.overlay = places::place_grids_overlay(grids, std::move(scene.overlay));
    std::vector<picture::Ink> keys = places::place_grid_keys();
    keys.insert(keys.end(), scene.keys.begin(), scene.keys.end());
    scene.keys = std::move(keys);
  }
  scene.title = r.title.empty() ? default_title(world.name, pose, scene) : r.title;
  if (r.title.empty() && *preset != sim::SonarPreset::ideal) {
    scene.title += "; sonar model " + std::string(sim::sonar_preset_name(*preset)) + ", seed " + std::to_string(r.seed);
  }
  if (!grids.empty() && r.title.empty()) scene.title += "; " + std::to_string(grids.size()) + " place grid" + (grids.size() == 1 ? "" : "s");
  if (graph && r.title.empty()) {
    char extra[160];
    std::snprintf(extra, sizeof extra, "; %zu places, %zu doors", graph->places().size(), graph->doors().size());
    scene.title += extra;
    if (route.found) {
      std::snprintf(extra, sizeof extra, "; route %s: %zu doors, %.1f m", r.route.c_str(), route.legs.size(), route.length);
      scene.title += extra;
    }
  }
  sim::RenderOptions options;
  options.pixels_per_metre = r.scale;
  const auto s = sim::render_file(scene, options, r.output);
  if (!s) return fail(s.error().describe());
  return 0;
}

}  // namespace robuter::simtool
