// SPDX-License-Identifier: GPL-3.0-or-later
// The run: temporary world with the start moved, the firmware with the emulated pan-tilt, AG, Ad.
#include "tools/robuter-doors-run/crossing_run.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "hal/sim/rng.hpp"
#include "modules/doors/doors_module.hpp"
#include "modules/emergency/emergency.hpp"
#include "modules/gate/gate_module.hpp"
#include "modules/firmware/sim_firmware.hpp"
#include "tools/robuter-doors-run/crossing_picture.hpp"

namespace robuter::test {

namespace {
// The world file with its [start] moved; the caller removes the file.
std::string moved_world(const std::string& file, double dx, double dy, double dh) {
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  auto shift = [&](const char* key, double by) {
    const std::regex re(std::string("(\\[start\\][^\\[]*?\\n") + key + "\\s*=\\s*)([-0-9.]+)");
    std::smatch m;
    if (std::regex_search(text, m, re)) {
      const double v = std::stod(m[2].str()) + by;
      text = m.prefix().str() + m[1].str() + std::to_string(v) + m.suffix().str();
    }
  };
  shift("x", dx);
  shift("y", dy);
  shift("heading_deg", dh);
  static int n = 0;
  const std::string out = (std::filesystem::temp_directory_path() /
                           ("robuter-doors-" + std::to_string(::getpid()) + "-" + std::to_string(n++) + ".toml"))
                              .string();
  std::ofstream(out) << text;
  return out;
}

// XD's words for a state, and the reason when it failed.
std::string words(const ModeStatus& s) {
  std::string w(word(s.state));
  if (s.state == ModeState::failed) w += " " + std::string(word(s.reason));
  return w;
}

// How a mode ended: `ok`, or "failed <reason>" in XD's words.
std::string mode_end(const ModeStatus& s, const char* ok) {
  if (s.state == ModeState::failed) return "failed " + std::string(word(s.reason));
  return ok;
}
}  // namespace

CrossingSetup seeded_start(const std::string& world, std::uint64_t seed, double max_lateral_m, double max_heading_deg) {
  sim::Rng rng(seed * 7919 + 17);
  CrossingSetup s;
  s.world = world;
  s.dx_m = (2.0 * rng.uniform() - 1.0) * max_lateral_m;
  s.dheading_deg = (2.0 * rng.uniform() - 1.0) * max_heading_deg;
  s.seed = seed;
  return s;
}

CrossingResult run_crossing(const CrossingSetup& s) {
  CrossingResult r;
  const std::string world = moved_world(s.world, s.dx_m, s.dy_m, s.dheading_deg);
  hal::SimOptions sim;
  sim.seed = s.seed;
  sim.sonar_model = s.sonar_model;
  sim.odometry_noise = s.odometry_noise;
  {
    SimFirmware fw(world, s.config, sim, true);
    std::filesystem::remove(world);
    if (!fw.ok()) {
      r.log = fw.error();
      return r;
    }
    r.started = true;
    // The picture's scans: the last one the finder saw before it ended (the scanner stops and
    // clears its scan once no mode wants it), then the last one of the crossing.
    std::vector<ScanSnapshot> snaps(s.picture.empty() ? 0 : 1);
    auto snapshot = [&](ScanSnapshot& into, const char* label) {
      into = ScanSnapshot{fw.bb().pan_tilt_scan.reader().peek(), fw.bb().posture.reader().peek(), fw.sim().robot().pose(), label};
    };
    fw.set_tick_observer([&] {
      if (fw.sim().robot().bumper()) r.contact = true;
      const ModeState g = fw.bb().gate_status.reader().peek().state;
      if (snaps.size() == 1 && (g == ModeState::searching || g == ModeState::moving) &&
          fw.bb().pan_tilt_scan.reader().peek().sweeps > 0)
        snapshot(snaps[0], "pan-tilt scan the passage finder ended on");
    });
    auto gate = [&] { return fw.bb().gate_status.reader().peek(); };
    auto doors = [&] { return fw.bb().doors_status.reader().peek(); };
    const double t0 = fw.seconds();
    fw.ask("AG");
    // Poll XD now and then, as a client would (the link stays alive for the comm watchdog).
    auto run_until_end = [&](auto done, int max_ticks) {
      for (int i = 0; i < max_ticks && !done(); i += 500) {
        fw.run_until(done, 500);
        if (!done()) fw.ask("XD");
        if (s.trace_every > 0) {  // the finder's progress: pose, state, manoeuvres, the envelope's stops
          const auto& q = fw.sim().robot().pose();
          const auto& e = fw.bb().emergency.reader().peek();
          const auto* gm = fw.module<GateModule>("gate");
          std::printf("  gate t %7.2f pose (%.3f, %.3f, %6.1f) state %d manoeuvres %u lateral %.0f mm heading %.1f deg "
                      "front %.0f mm | protective %d stops %u granted %u%% held %d trips %u\n",
                      fw.seconds(), q.x, q.y, q.theta * 180 / M_PI, static_cast<int>(gate().state),
                      gm ? gm->logic().manoeuvres() : 0, gm ? gm->logic().lateral_error_mm() : 0.0,
                      gm ? gm->logic().heading_error_deg() : 0.0, gm ? gm->logic().front_distance_mm() : 0.0,
                      e.protective, e.protective_stops, e.granted_pct, e.held, e.trips);
        }
      }
    };
    run_until_end([&] { return gate().state == ModeState::aligned || gate().state == ModeState::failed; }, 30000);
    r.gate = mode_end(gate(), gate().state == ModeState::aligned ? "aligned" : "running");
    r.gate_s = fw.seconds() - t0;
    r.log += *fw.ask("XD") + "\n";
    if (gate().state == ModeState::failed) r.log += *fw.ask("BP") + "\n";
    // With [gate] hand_over the crossing starts by itself once aligned (the seed's hand-over): no Ad.
    const bool hand_over = s.config.gate.hand_over && gate().state == ModeState::aligned;
    if (hand_over || (s.send_ad && (gate().state == ModeState::aligned || s.ad_even_if_gate_failed))) {
      const double t1 = fw.seconds();
      if (!hand_over) fw.ask("Ad");
      const std::uint64_t ad_tick = fw.kernel().tick();
      auto ended = [&] { return doors().state == ModeState::crossed || doors().state == ModeState::failed; };
      for (int i = 0; i < 60000 && !ended(); ++i) {
        fw.step();
        if (i % 500 == 499 && (s.close_link_after_ticks < 0 || fw.kernel().tick() - ad_tick < static_cast<std::uint64_t>(s.close_link_after_ticks)))
          fw.ask("XD");
        if (r.mask_during < 0 && doors().state == ModeState::crossing)
          r.mask_during = fw.bb().emergency.reader().peek().enabled;
        if (s.trace_every > 0 && i % s.trace_every == 0) {
          const auto& q = fw.sim().robot().pose();
          const auto* dm = fw.module<DoorsModule>("doors");
          const auto& v = dm->crossing().view();
          std::printf("  t %7.2f pose (%.3f, %.3f, %6.1f) state %d threats L%d R%d entered %d clear %d cmd %d %d open %.0f%s\n",
                      fw.seconds(), q.x, q.y, q.theta * 180 / M_PI, static_cast<int>(doors().state), v.threats.left,
                      v.threats.right, v.entered, v.clear, fw.bb().posture.reader().peek().left,
                      fw.bb().posture.reader().peek().right, v.opening_mm, v.too_narrow ? " NARROW" : "");
          if (s.trace_every == 1 || s.trace_echoes) {
            ptu::Echoes e;
            const Posture& po = fw.bb().posture.reader().peek();
            ptu::locate_echoes(fw.bb().pan_tilt_scan.reader().peek(), SectorPose{po.x, po.y, po.theta}, fw.kernel().tick(), 600,
                               ptu::EchoGeometry{}, e);
            for (int k = 0; k < 72; ++k)
              if (e[k].valid && !e[k].far && e[k].range_mm < 1200)
                std::printf("    k%02d b %6.1f ±%4.1f r %5.0f (%5.0f,%5.0f)\n", k, e[k].bearing_deg, e[k].spread_deg, e[k].range_mm, e[k].x_mm, e[k].y_mm);
          }
        }
        const std::uint64_t since = fw.kernel().tick() - ad_tick;
        if (s.unplug_after_ticks >= 0 && since == static_cast<std::uint64_t>(s.unplug_after_ticks)) fw.unplug_ptu();
        if (s.cancel_after_ticks >= 0 && since == static_cast<std::uint64_t>(s.cancel_after_ticks)) fw.ask("Af");
        if (s.close_link_after_ticks >= 0 && since == static_cast<std::uint64_t>(s.close_link_after_ticks)) fw.close_client();
        if (s.shutdown_after_ticks >= 0 && since == static_cast<std::uint64_t>(s.shutdown_after_ticks)) {
          fw.kernel().shutdown();  // every close(): the crossing must give the mask back
          r.doors = mode_end(doors(), doors().state == ModeState::crossed ? "crossed" : "running");
          r.mask_after = fw.bb().emergency.reader().peek().enabled;
          if (const auto* em = fw.module<EmergencyModule>("emergency")) r.mask_after = em->enabled();
          r.stopped = fw.bb().posture.reader().peek().left == 0 && fw.bb().posture.reader().peek().right == 0;
          r.contact = r.contact || fw.sim().robot().bumper();
          r.pan_tilt = words(fw.bb().pan_tilt_status.reader().peek());
          return r;
        }
      }
      r.doors = mode_end(doors(), ended() ? "crossed" : "running");
      r.crossing_s = fw.seconds() - t1;
      if (!s.picture.empty()) {
        snaps.emplace_back();
        snapshot(snaps.back(), ("last pan-tilt scan of the crossing (" + r.doors + ")").c_str());
        char title[200];
        std::snprintf(title, sizeof title, "%s, start dx %+.2f m, %+.1f deg: %s (AG %.0f s, Ad %.0f s)",
                      std::filesystem::path(s.world).stem().c_str(), s.dx_m, s.dheading_deg, r.doors.c_str(), r.gate_s,
                      r.crossing_s);
        auto laid = write_crossing_picture(fw.sim(), s.config, snaps, title, s.picture);
        if (laid) r.picture_layout = std::move(laid).value();
        else r.picture_error = laid.error().message;
      }
      fw.run_ticks(20);
      r.mask_after = fw.bb().emergency.reader().peek().enabled;
      if (s.close_link_after_ticks < 0)
        if (auto d = fw.ask("XD")) r.log += *d + "\n";
    }
    r.total_s = fw.seconds() - t0;
    r.pan_tilt = words(fw.bb().pan_tilt_status.reader().peek());
    const auto& pose = fw.sim().robot().pose();
    r.end_x = pose.x;
    r.end_y = pose.y;
    r.end_heading_deg = pose.theta * 180.0 / M_PI;
    // Body rectangle corners: axle 695 mm behind the front, 330 mm ahead of the rear.
    double min_y = 1e9;
    for (double ax : {0.695, -0.330})
      for (double ay : {0.35, -0.35})
        min_y = std::min(min_y, pose.y + ax * std::sin(pose.theta) + ay * std::cos(pose.theta));
    r.body_through = min_y > 4.05;
    const Posture& p = fw.bb().posture.reader().peek();
    r.stopped = p.left == 0 && p.right == 0;
  }
  return r;
}

}  // namespace robuter::test
