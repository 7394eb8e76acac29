// robuter_doors_run: one door crossing (AG then Ad) on the simulated firmware from a seeded or a
// given start; prints how it ended and can draw it (trail and pan-tilt scans) — for looking into
// one start of the bench, and for the picture in docs/DOORS.md.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>

#include "hal/sim/render.hpp"
#include "tests/doors_sim/crossing_run.hpp"

int main(int argc, char** argv) {
  using namespace robuter::test;
  CLI::App app{"One door crossing on the simulated robot: AG, then Ad; the result line, optionally a picture."};
  std::string world = ROBUTER_WORLDS_DIR "/door90.toml";
  int seed = 1, count = 1, trace = 0;
  double dx = 0.0, dh = 0.0;
  bool fixed = false, noise = false, any = false, echoes = false, log = false;
  std::string picture;
  app.add_option("--world", world, "world file (door90, door100, gap70 …)")->check(CLI::ExistingFile);
  app.add_option("--seed", seed, "first seeded start (the bench's numbering)")->check(CLI::PositiveNumber);
  app.add_option("--count", count, "starts from --seed on")->check(CLI::PositiveNumber);
  app.add_option("--dx", dx, "a given start instead: lateral offset, m")->each([&](const std::string&) { fixed = true; });
  app.add_option("--dheading", dh, "a given start instead: heading offset, degrees")->each([&](const std::string&) { fixed = true; });
  app.add_flag("--noise", noise, "sonar and odometry noise on");
  app.add_flag("--ad-anyway", any, "send Ad even when the passage finder failed");
  app.add_option("--trace", trace, "print pose and crossing decisions every N ticks");
  app.add_flag("--echoes", echoes, "with --trace: the localised echoes closer than 1.2 m too");
  app.add_flag("--log", log, "print the XD replies of the run");
  app.add_option("--picture", picture, "draw the (last) run to this .png, .svg or .pdf file");
  CLI11_PARSE(app, argc, argv);
  int failures = 0;
  for (int n = seed; n < seed + count; ++n) {
    CrossingSetup s = seeded_start(world, static_cast<std::uint64_t>(n));
    if (fixed) {
      s.dx_m = dx;
      s.dheading_deg = dh;
    }
    s.sonar_noise = s.odometry_noise = noise;
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
      std::fprintf(stderr, "robuter_doors_run: %s\n", r.picture_error.c_str());
      return 2;
    }
  }
  robuter::sim::release_render_caches();
  return failures == 0 ? 0 : 1;
}
