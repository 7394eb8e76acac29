// SPDX-License-Identifier: GPL-3.0-or-later
// robuter-doors-run: one door crossing (AG then Ad) on the simulated firmware from a seeded or a
// given start; prints how it ended and can draw it (trail and pan-tilt scans) — for looking into
// one start of the bench, and for the picture in docs/DOORS.md.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

#include "cli/parse_or_usage.hpp"
#include "hal/sim/render.hpp"
#include "tools/robuter-doors-run/crossing_run.hpp"

namespace {
namespace fs = std::filesystem;

// The worlds folder, as robuterd finds its default world: an installed robuter-doors-run takes its
// own prefix's (<bindir>/../share/robuterd/worlds, wherever the prefix is); a build-tree one
// finds none there and takes the source tree's. --worlds-dir overrides both.
std::string default_worlds_dir() {
  std::error_code ec;
  const auto exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto dir = (exe.parent_path() / ROBUTER_BIN_TO_DATA / "worlds").lexically_normal();
    if (fs::is_directory(dir, ec)) return dir.string();
  }
  return ROBUTER_SOURCE_WORLDS_DIR;
}

// --world: an existing file as given; else, when it names no folder, a world of the worlds folder,
// with or without its .toml ("door90"). Empty when there is none.
std::string find_world(const std::string& world, const std::string& dir) {
  std::error_code ec;
  if (fs::is_regular_file(world, ec)) return world;
  if (world.find('/') != std::string::npos) return {};
  for (const std::string& name : {world, world + ".toml"}) {
    const fs::path p = fs::path(dir) / name;
    if (fs::is_regular_file(p, ec)) return p.string();
  }
  return {};
}
}  // namespace

int main(int argc, char** argv) {
  using namespace robuter::test;
  CLI::App app{"One door crossing on the simulated robot: AG, then Ad; the result line, optionally a picture."};
  std::string world_arg = "door90";
  std::string worlds_dir = default_worlds_dir();
  int seed = 1, count = 1, trace = 0;
  double dx = 0.0, dh = 0.0;
  bool fixed = false, noise = false, any = false, echoes = false, log = false;
  std::string picture, sonar_model;
  app.add_option("--world", world_arg, "world: a name in the worlds folder (door90, door100, gap70 …) or a file")
      ->capture_default_str();
  app.add_option("--worlds-dir", worlds_dir, "the worlds folder")->capture_default_str();
  app.add_option("--seed", seed, "first seeded start (the bench's numbering)")->check(CLI::PositiveNumber);
  app.add_option("--count", count, "starts from --seed on")->check(CLI::PositiveNumber);
  app.add_option("--dx", dx, "a given start instead: lateral offset, m")->each([&](const std::string&) { fixed = true; });
  app.add_option("--dheading", dh, "a given start instead: heading offset, degrees")->each([&](const std::string&) { fixed = true; });
  app.add_flag("--noise", noise, "sonar (the stress model) and odometry noise on");
  app.add_option("--sonar-model", sonar_model, "the simulator's sonar model, odometry noise on too: ideal, stress or realistic (docs/SIMULATOR.md)")
      ->check(CLI::IsMember({"ideal", "stress", "realistic"}));
  app.add_flag("--ad-anyway", any, "send Ad even when the passage finder failed");
  app.add_option("--trace", trace, "print pose and crossing decisions every N ticks");
  app.add_flag("--echoes", echoes, "with --trace: the localised echoes closer than 1.2 m too");
  app.add_flag("--log", log, "print the XD replies of the run");
  app.add_option("--picture", picture, "draw the (last) run to this .png, .svg or .pdf file");
  if (const auto status = robuter::cli::parse_or_usage(app, argc, argv)) return *status;
  const std::string world = find_world(world_arg, worlds_dir);
  if (world.empty()) {
    std::fprintf(stderr, "robuter-doors-run: no world '%s' (neither a file nor in %s)\n", world_arg.c_str(), worlds_dir.c_str());
    return 2;
  }
  int failures = 0;
  for (int n = seed; n < seed + count; ++n) {
    CrossingSetup s = seeded_start(world, static_cast<std::uint64_t>(n));
    if (fixed) {
      s.dx_m = dx;
      s.dheading_deg = dh;
    }
    s.odometry_noise = noise || !sonar_model.empty();
    if (noise) s.sonar_model = robuter::sim::SonarPreset::stress;
    if (!sonar_model.empty()) s.sonar_model = *robuter::sim::sonar_preset(sonar_model);  // checked by IsMember
    s.ad_even_if_gate_failed = any;
    s.trace_every = trace;
    s.trace_echoes = echoes;
    if (n == seed + count - 1) s.picture = picture;
    const CrossingResult r = run_crossing(s);
    const bool ok = r.doors == "crossed" && !r.contact && r.body_through;
    failures += ok ? 0 : 1;
    std::printf("seed %d dx %+.2f m heading %+5.1f° | gate %-20s %5.1f s | doors %-20s %5.1f s | contact %d through %d stopped %d "
                "mask %d/%d | end (%.3f, %.3f, %.1f°)\n",
                n, s.dx_m, s.dheading_deg, r.gate.c_str(), r.gate_s, r.doors.c_str(), r.crossing_s, r.contact, r.body_through,
                r.stopped, r.mask_during, r.mask_after, r.end_x, r.end_y, r.end_heading_deg);
    if (log || !r.started) std::printf("%s", r.log.c_str());
    if (!r.picture_error.empty()) {
      std::fprintf(stderr, "robuter-doors-run: %s\n", r.picture_error.c_str());
      return 2;
    }
  }
  robuter::sim::release_render_caches();
  return failures == 0 ? 0 : 1;
}
