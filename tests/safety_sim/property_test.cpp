// SPDX-License-Identifier: GPL-3.0-or-later
// Acceptance 5: thousands of seeded random command sequences checked on every tick of the firmware.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hal/sim/rng.hpp"
#include "hal/sim/world_io.hpp"
#include "modules/emergency/emergency.hpp"
#include "modules/emergency/watchdog_sets.hpp"
#include "modules/planner/lib/map_file.hpp"
#include "tools/robuter-plan/world_map.hpp"
#include "tests/safety_sim/support.hpp"
#include "tests/support/sample.hpp"

namespace robuter::test::safety_sim {
namespace {

constexpr int kShards = 4;  // the sequences are split over this many tests (ctest runs them in parallel)

// Sequences in the whole property test: thousands normally, fewer under the sanitizers (about
// ten times slower); ROBUTER_SAFETY_SIM_SEQUENCES overrides (longer soak runs).
int total_sequences() {
  if (const char* env = std::getenv("ROBUTER_SAFETY_SIM_SEQUENCES")) return std::max(kShards, std::atoi(env));
  return sample(1000, 100);  // 100 under the sanitizers; 10,000 in make bench
}

// The sonar model of the noisy half of the sequences: stress, or ROBUTER_SAFETY_SIM_SONAR's.
sim::SonarPreset noisy_sonar_model() {
  const char* env = std::getenv("ROBUTER_SAFETY_SIM_SONAR");
  if (env == nullptr) return sim::SonarPreset::stress;
  const auto named = sim::sonar_preset(env);
  if (!named) ADD_FAILURE() << "ROBUTER_SAFETY_SIM_SONAR=" << env << ": expected " << sim::sonar_preset_choices();
  return named.value_or(sim::SonarPreset::stress);
}

// Debugging a failing seed: ROBUTER_SAFETY_SIM_SEED=n runs only that sequence (in shard 0) and
// ROBUTER_SAFETY_SIM_TRACE=from:to prints every tick of that range (command, drive, verdict, pose).
struct TraceWindow {
  std::uint64_t from = 1, to = 0;  // empty when from > to
};
// The window asked for in the environment (none when unset or malformed).
TraceWindow trace_window() {
  TraceWindow w;
  if (const char* env = std::getenv("ROBUTER_SAFETY_SIM_TRACE")) {
    unsigned long long a = 0, b = 0;
    if (std::sscanf(env, "%llu:%llu", &a, &b) == 2) w = {a, b};
  }
  return w;
}

// A random world: a 10 × 10 m walled arena with 3–10 boxes of any size and angle, and a start
// pose at least 30 cm from everything (nearer, the sonar's blanking zone and the body's corners
// could start in contact range). Empty when no valid start was found.
std::string random_world(sim::Rng& rng) {
  for (int attempt = 0; attempt < 50; ++attempt) {
    std::string boxes;
    const int n = 3 + static_cast<int>(rng.uniform(0.0, 8.0));
    for (int i = 0; i < n; ++i)
      boxes += fmt::format("[[box]]\nname = \"b{}\"\ncenter = [{:.3f}, {:.3f}]\nsize = [{:.3f}, {:.3f}]\nangle_deg = {:.1f}\n", i,
                           rng.uniform(0.8, 9.2), rng.uniform(0.8, 9.2), rng.uniform(0.2, 1.2), rng.uniform(0.2, 1.2),
                           rng.uniform(0.0, 180.0));
    for (int s = 0; s < 20; ++s) {
      const sim::Pose start{rng.uniform(1.0, 9.0), rng.uniform(1.0, 9.0), rng.uniform(-sim::kPi, sim::kPi)};
      const std::string toml = fmt::format(
          "[world]\nname = \"random\"\nunits = \"m\"\n[start]\nx = {:.4f}\ny = {:.4f}\nheading_deg = {:.3f}\n"
          "[[wall]]\nname = \"arena\"\npoints = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]\nclosed = true\n{}",
          start.x, start.y, sim::rad_to_deg(start.theta), boxes);
      auto w = sim::parse_world_toml(toml, "random.toml", geometry());
      if (!w) continue;  // start inside or touching an obstacle
      if (body_clearance(w.value(), geometry(), *w.value().start) < 0.30) continue;
      return toml;
    }
  }
  return {};
}

// The obstacle rule under test: the envelope (default) or, for the comparison figures of
// docs/SAFETY.md, the seed's (ROBUTER_EMERGENCY_RULE=seed).
std::string rule_under_test() {
  const char* env = std::getenv("ROBUTER_EMERGENCY_RULE");
  if (env && (std::string(env) == "envelope" || std::string(env) == "seed")) return env;
  return Config{}.emergency.rule;
}

// A configuration varied per sequence: detection mask, latch, communication limit, auto-toggle,
// motion time-out.
Config random_config(sim::Rng& rng) {
  Config c = core_config();
  c.enabled_modules->push_back("planner");  // XG: an automatic mode to start and interrupt
  c.enabled_modules->push_back("demo");     // XT1: another
  c.emergency.rule = rule_under_test();
  // ROBUTER_EMERGENCY_NARROW_ARCS=0: the echo arcs marked whole (the comparison of docs/SAFETY.md §13).
  if (const char* env = std::getenv("ROBUTER_EMERGENCY_NARROW_ARCS")) c.emergency.narrow_arcs = std::string(env) != "0";
  if (rng.uniform() < 0.3) c.emergency.mask = static_cast<std::uint32_t>(rng.uniform(0.0, 8.0));
  c.emergency.latch = rng.uniform() < 0.85;
  if (rng.uniform() < 0.3) c.emergency.comm_limit_ticks = 100 + static_cast<std::uint32_t>(rng.uniform(0.0, 1400.0));
  c.emergency.auto_toggle = rng.uniform() < 0.25;
  if (rng.uniform() < 0.2) c.emergency.motion_timeout_ms = 500 + static_cast<std::uint32_t>(rng.uniform(0.0, 4500.0));
  return c;
}

// An integer in [lo, hi].
int irand(sim::Rng& rng, int lo, int hi) { return lo + static_cast<int>(rng.uniform(0.0, hi - lo + 1.0)); }

// The a-priori map a sequence's firmware is given ([planner] map_file): its walls explain the
// ring's echoes and narrow their arcs (docs/SAFETY.md §13, "Narrowing"), so a wrong map must not
// open a way into an obstacle either.
enum class MapKind {
  none,     // no map (the sequences as before maps were drawn)
  exact,    // the world's edges, odometry set to the world's frame
  shifted,  // the same edges displaced 5-40 cm
  other,    // the edges of another random world (the arena's walls right, every box wrong)
};
const char* map_kind_name(MapKind k) {
  switch (k) {
    case MapKind::none: return "none";
    case MapKind::exact: return "exact";
    case MapKind::shifted: return "shifted";
    case MapKind::other: return "other";
  }
  return "?";
}

// Writes the map of `kind` for the world `toml` next to it and returns its path (empty for none).
// Drawn from its own generator, so the sequences without a map are the ones they always were.
std::string write_map(MapKind kind, const std::string& toml, const std::string& world_path, sim::Rng& mrng) {
  if (kind == MapKind::none) return {};
  const std::string source = kind == MapKind::other ? random_world(mrng) : toml;
  auto w = sim::parse_world_toml(source.empty() ? toml : source, "map.toml", geometry());
  if (!w) return {};
  const plan::MapGeometry g{220, 220, 0.05, plan::Point2{-0.5, -0.5}};  // the 10 m arena and 0.5 m round it
  plan::OccupancyMap exact(g);
  plan::tool::rasterise_world(w.value(), exact);
  plan::OccupancyMap map = exact;
  if (kind == MapKind::shifted) {
    const double a = mrng.uniform(-sim::kPi, sim::kPi), d = mrng.uniform(0.05, 0.40);
    const int dx = static_cast<int>(std::lround(d * std::cos(a) / g.resolution));
    const int dy = static_cast<int>(std::lround(d * std::sin(a) / g.resolution));
    map = plan::OccupancyMap(g);
    for (int y = 0; y < g.height; ++y)
      for (int x = 0; x < g.width; ++x)
        if (exact.state({x, y}) == plan::CellState::Occupied && map.contains({x + dx, y + dy})) map.mark_occupied({x + dx, y + dy});
  }
  const std::string path = world_path + ".map";
  if (!plan::save_map(map, path)) return {};
  return path;
}

// Random wheel speeds: straight, a curve, a rotation or anything, up to 60 cm/s.
std::pair<int, int> random_speeds(sim::Rng& rng) {
  const double k = rng.uniform();
  const int v = irand(rng, -60, 60);
  if (k < 0.35) return {v, v};
  if (k < 0.55) return {v, -v};
  if (k < 0.8) return {v, std::clamp(v + irand(rng, -25, 25), -60, 60)};
  return {v, irand(rng, -60, 60)};
}

// Totals over a shard, for the figures.
struct Totals {
  long sequences = 0, ticks = 0, commands = 0, stop_bytes = 0, no_reply = 0, noisy = 0;
  long protective_stops = 0;              // protective stops (envelope: obstacle evidence in the way)
  double emergency_max_us = 0;            // longest activation of the emergency process, µs
  long latched_ticks = 0, moving_ticks = 0, us_on_ticks = 0, contacts_us_off = 0;
  long latched_moving = 0;                // ticks with a non-zero speed at the drive while latched
  long ungranted = 0;                     // ticks with a non-zero speed the gate no longer grants
  long longest_disagreement = 0;          // longest such run, ticks
  long contact_sequences = 0;             // sequences with a contact while the sonar watched
  std::string contact_seeds;              // their seeds, main sensor and body point, for the report
  std::array<long, protocol::kEnumerators<EmergencyCause>> trips_by_cause{};  // by EmergencyCause of the verdict that tripped
  long trips = 0;
  double min_clearance_us_on = 1e9;
  long automatic_starts = 0;              // XG / XT1 acknowledged
  long automatic_ticks = 0;               // ticks an automatic mode drove
  long automatic_after_operator = 0;      // ticks an automatic mode drove after an operator's command ended it
  long resumed_by_itself = 0;             // ticks an operator's motion drove after a trip or stop forgot it
  std::string arbiter_violation;          // the first of those two, for the report
  std::array<long, 4> mapped{};           // sequences by MapKind given a map (none is not counted)
  long narrowed_cells = 0;                // arc cells the map-explained narrowing left out
};

// The arbiter's invariants (docs/SAFETY.md §1), from the commands the sequence sent and every
// tick's motion command: an automatic mode drives only between its acknowledged start and the
// next operator command (or trip); an operator's motion drives only between its acknowledged
// `AM`/`AW` and the next trip, protective stop, `AM 0 0`, `ASF` or stop byte. One tick of grace
// after the acknowledgement (the command reaches the drive in the tick it is taken).
struct ArbiterMonitor {
  bool automatic_may = false;     // an automatic start was acknowledged and nothing ended it since
  bool operator_may = false;      // an operator's motion is in force
  std::uint64_t since = 0;        // tick of the last change of either, ticks
  std::uint32_t trips = 0, protective = 0;  // counters last seen
  long automatic_ticks = 0, automatic_after_operator = 0, resumed_by_itself = 0;
  std::string first;              // the first violation
  bool paused = false;            // a line is being answered: judged from its answer on

  void changed(std::uint64_t tick) { since = tick; }
  void check(SimFirmware& fw) {
    const std::uint64_t tick = fw.kernel().tick();
    const EmergencyState& e = fw.bb().emergency.reader().peek();
    if (e.trips != trips) {
      trips = e.trips;
      automatic_may = operator_may = false;
      changed(tick);
    }
    if (e.protective_stops != protective) {
      protective = e.protective_stops;
      operator_may = false;  // a protective stop forgets the operator's motion, not a mode's
      changed(tick);
    }
    const MotionCommand& c = fw.bb().motion_command.reader().peek();
    if (paused || c.stop || (c.left == 0 && c.right == 0) || tick <= since + 1) return;
    const bool automatic = emergency::automatic(c.source);
    if (automatic) ++automatic_ticks;
    if (automatic && !automatic_may) {
      ++automatic_after_operator;
      if (first.empty()) first = fmt::format("tick {}: automatic source {} drives {} {} after an operator's command or a trip",
                                             tick, static_cast<int>(c.source), c.left, c.right);
    } else if (!automatic && !operator_may) {
      ++resumed_by_itself;
      if (first.empty()) first = fmt::format("tick {}: the operator's motion {} {} drives again by itself", tick, c.left, c.right);
    }
  }
  // A line was answered `reply` at `tick`.
  void sent(const std::string& line, const std::string& reply, std::uint64_t tick) {
    changed(tick);
    if (reply != "ack") return;
    const auto is = [&](const char* p) { return line.rfind(p, 0) == 0; };
    if (is("XG") || is("XT1")) {
      automatic_may = true;
      operator_may = false;
    } else if (is("AM") || is("AW") || is("ASF") || is("ASN") || is("XH") || is("XT0") || is("AT") || is("Af")) {
      automatic_may = false;
      if (is("AM")) operator_may = line != "AM 0 0";
      if (is("AW")) operator_may = true;
      if (is("ASF")) operator_may = false;  // XH, XT0, AT, Af, ASN leave an operator's motion as it is
    } else {
      return;
    }
    changed(tick);
  }
  void stop_byte(std::uint64_t tick) {
    automatic_may = operator_may = false;
    changed(tick);
  }
};

// One sequence: a random world, configuration and command list; the monitor checks every tick.
// Adds to the totals; `report` receives the seed, configuration, commands and world when an
// invariant broke (or a contact happened and `contacts_fail`).
void run_sequence(std::uint64_t seed, Totals& tot, std::string& report, bool contacts_fail) {
  sim::Rng rng(seed);
  const std::string toml = random_world(rng);
  if (toml.empty()) return;
  Config cfg = random_config(rng);
  TempWorld file(toml);
  sim::Rng mrng(seed ^ 0x6d61702d6b696e64ull);
  const double mk = mrng.uniform();
  const MapKind map_kind = mk < 0.5 ? MapKind::none : mk < 0.75 ? MapKind::exact : mk < 0.875 ? MapKind::shifted : MapKind::other;
  cfg.planner.map_file = write_map(map_kind, toml, file.path(), mrng);
  if (map_kind != MapKind::none && cfg.planner.map_file.empty()) {
    report = "seed " + std::to_string(seed) + ": the map was not written";
    return;
  }
  hal::SimOptions opt;
  opt.seed = seed;
  // Sonar noise and odometry noise in half the sequences: the stress sonar model, or the one
  // ROBUTER_SAFETY_SIM_SONAR names (realistic: issue #19's acceptance, in make bench).
  opt.odometry_noise = rng.uniform() < 0.5;
  if (opt.odometry_noise) {
    opt.sonar_model = noisy_sonar_model();
    ++tot.noisy;
  }
  SimFirmware fw(file.path(), cfg, opt);
  if (!fw.ok()) {
    report = "seed " + std::to_string(seed) + ": " + fw.error();
    return;
  }
  SafetyMonitor mon;
  mon.attach(fw);
  ArbiterMonitor arb;
  fw.set_tick_observer([&] {
    mon.check();
    arb.check(fw);
  });
  const TraceWindow tw = trace_window();
  if (tw.from <= tw.to) {
    fw.set_tick_observer([&] {
      mon.check();
      arb.check(fw);
      const std::uint64_t tick = fw.kernel().tick() - 1;
      if (tick < tw.from || tick > tw.to) return;
      const MotionCommand& c = fw.bb().motion_command.reader().peek();
      const EmergencyState& e = fw.bb().emergency.reader().peek();
      const Wheels w = commanded(fw);
      const auto& r = fw.bb().ranges.reader().peek();
      const auto& pose = fw.sim().robot().pose();
      std::string reads;
      for (int s = 1; s <= 24; ++s)
        if (r.read_tick[static_cast<std::size_t>(s - 1)] == tick) reads += fmt::format(" s{}={}", s, r.mm[static_cast<std::size_t>(s - 1)]);
      std::string env;
      if (const auto row = fw.kernel().find("emergency")) {
        if (auto* em = dynamic_cast<EmergencyModule*>(fw.kernel().row(*row).process); em && (w.left || w.right)) {
          const auto v = const_cast<emergency::RingEnvelope&>(em->envelope()).judge(w.left, w.right, true);
          env = fmt::format(" | env k {:.2f} miss {} obst {} at ({:.0f}, {:.0f})", v.fraction, v.missing, v.obstacle,
                            v.where.x() * 1000.0, v.where.y() * 1000.0);
        }
      }
      sim::Vec2 near;
      const double clear = body_clearance(fw.sim().world(), fw.sim().robot().params().geometry, pose, &near);
      std::printf("%llu cmd#%u %d %d%s src%d | drive %d %d | main %d watch %06x safety %u held %d latched %d cause %d "
                  "sensor %d | pose %.3f %.3f %.1f° clear %.0f mm at (%.0f, %.0f) bump %d |%s%s\n",
                  static_cast<unsigned long long>(tick), fw.bb().motion_command.reader().generation(), c.left, c.right, c.stop ? " stop" : "",
                  static_cast<int>(c.source), w.left, w.right, e.main_sensor, e.watch, e.safety_mm, e.held, e.latched,
                  static_cast<int>(e.cause), e.sensor, pose.x, pose.y, sim::rad_to_deg(pose.theta),
                  clear * 1000.0, near.x() * 1000.0, near.y() * 1000.0, fw.sim().robot().bumper(), reads.c_str(), env.c_str());
    });
  }
  std::string log;
  std::uint32_t last_trips = 0;
  // Counts each trip by its cause (the verdict's cause in the tick the trip counter moved).
  auto note_trips = [&] {
    const EmergencyState& e = fw.bb().emergency.reader().peek();
    if (e.trips != last_trips) {
      tot.trips += e.trips - last_trips;
      ++tot.trips_by_cause[static_cast<std::size_t>(e.cause)];
      last_trips = e.trips;
    }
  };
  // Sends one line, logs it and runs the reply's ticks with the monitor on.
  auto send = [&](const std::string& line) {
    log += line + "; ";
    ++tot.commands;
    arb.paused = true;
    const auto reply = fw.ask(line, 60);
    arb.paused = false;
    if (!reply) ++tot.no_reply;
    if (reply && *reply == "ack" && (line.rfind("XG", 0) == 0 || line == "XT1")) ++tot.automatic_starts;
    arb.sent(line, reply.value_or(""), fw.kernel().tick());
    note_trips();
  };
  auto stop_byte = [&] {
    log += "<0x18>; ";
    ++tot.stop_bytes;
    fw.send_raw("\x18");
    arb.stop_byte(fw.kernel().tick());
  };
  if (map_kind != MapKind::none) {
    // Odometry in the map's frame (the world's), as an operator starting a mapped run would set it.
    const sim::Pose st = *fw.sim().world().start;
    long theta = std::lround(sim::rad_to_deg(st.theta) * 100.0);
    if (theta <= -18000) theta += 36000;  // the protocol's (−18000, 18000]
    send(fmt::format("AC {} {} {}", std::lround(st.x * 10000.0), std::lround(st.y * 10000.0), theta));
    ++tot.mapped[static_cast<std::size_t>(map_kind)];
  }
  const int actions = irand(rng, 12, 24);
  for (int a = 0; a < actions; ++a) {
    const double k = rng.uniform();
    const Posture& p = fw.bb().posture.reader().peek();
    if (k < 0.34) {
      const auto [l, r] = random_speeds(rng);
      send(fmt::format("AM {} {}", l, r));
    } else if (k < 0.39) {
      send("AM 0 0");
    } else if (k < 0.42) {
      send("ASN");
    } else if (k < 0.45) {
      send("ASF");
    } else if (k < 0.53) {
      send(fmt::format("AW {} {} {}", p.x + irand(rng, -15000, 15000), p.y + irand(rng, -15000, 15000),
                       irand(rng, -17999, 18000)));
    } else if (k < 0.55) {
      send(fmt::format("AC {} {} {}", irand(rng, -50000, 50000), irand(rng, -50000, 50000), irand(rng, -17999, 18000)));
    } else if (k < 0.59) {
      std::string t = "UT";
      for (int s = 0; s < 24; ++s) t += rng.uniform() < 0.7 ? '1' : '0';
      send(t);
    } else if (k < 0.63) {
      send(rng.uniform() < 0.5 ? "Uu0" : "Uu1");
    } else if (k < 0.77) {
      send("XR");
    } else if (k < 0.79) {
      stop_byte();
    } else if (k < 0.82) {
      send(rng.uniform() < 0.5 ? "XE" : "BO");
    } else if (k < 0.835) {
      // Node delays from the seed's 3 ticks to 10 s a node (a full scan of a minute), log-uniform
      // above 10: the envelope must take the age of every reading into account.
      const int ud = rng.uniform() < 0.5 ? irand(rng, 3, 10)
                                         : static_cast<int>(std::lround(std::exp(rng.uniform(std::log(10.0), std::log(1000.0)))));
      send(fmt::format("UD{}", ud));
    } else if (k < 0.845) {
      send(fmt::format("Ut{}", irand(rng, 15, 60)));
    } else if (k < 0.87) {
      const int quiet = irand(rng, 200, 1600);  // silence: comm loss, hold expiry, motion time-out
      log += fmt::format("<quiet {}>; ", quiet);
      for (int i = 0; i < quiet; ++i) {
        fw.step();
        note_trips();
      }
    } else if (k < 0.905) {
      // An automatic mode — the planner to a point near the robot, or the demonstration course —
      // given time to drive before the next action interrupts it.
      if (rng.uniform() < 0.7) send("ASN");
      if (rng.uniform() < 0.7)
        send(fmt::format("XG {} {}", p.x + irand(rng, -20000, 20000), p.y + irand(rng, -20000, 20000)));
      else
        send("XT1");
      const int drive = irand(rng, 100, 800);
      for (int i = 0; i < drive; ++i) {
        fw.step();
        note_trips();
      }
    } else if (k < 0.92) {
      send(rng.uniform() < 0.5 ? "XH" : "XT0");  // an automatic mode's own stop
    } else {
      // Requests in quick succession: several command changes close together.
      const auto [l, r] = random_speeds(rng);
      send(fmt::format("AM {} {}", l, r));
      const int mode = irand(rng, 0, 2);
      if (mode == 0) send("XR");
      if (mode == 1) {
        const auto [l2, r2] = random_speeds(rng);
        send(fmt::format("AM {} {}", l2, r2));
      }
      if (mode == 2) stop_byte();
    }
    const int wait = irand(rng, 1, 80);
    for (int i = 0; i < wait; ++i) {
      fw.step();
      note_trips();
    }
  }
  ++tot.sequences;
  tot.protective_stops += fw.bb().emergency.reader().peek().protective_stops;
  if (const auto row = fw.kernel().find("emergency")) {
    tot.emergency_max_us = std::max(tot.emergency_max_us, static_cast<double>(fw.kernel().stats(*row).max_ns) / 1000.0);
    if (auto* em = dynamic_cast<EmergencyModule*>(fw.kernel().row(*row).process))
      tot.narrowed_cells += static_cast<long>(em->envelope().grid().narrowed_cells());
  }
  tot.ticks += static_cast<long>(mon.ticks);
  tot.latched_ticks += static_cast<long>(mon.latched_ticks);
  tot.moving_ticks += static_cast<long>(mon.moving_ticks);
  tot.us_on_ticks += static_cast<long>(mon.us_on_ticks);
  tot.contacts_us_off += static_cast<long>(mon.contact_us_off);
  tot.min_clearance_us_on = std::min(tot.min_clearance_us_on, mon.min_clearance_us_on);
  tot.latched_moving += static_cast<long>(mon.latched_moving);
  tot.ungranted += static_cast<long>(mon.ungranted);
  tot.longest_disagreement = std::max(tot.longest_disagreement, static_cast<long>(mon.longest_disagreement));
  tot.automatic_ticks += arb.automatic_ticks;
  tot.automatic_after_operator += arb.automatic_after_operator;
  tot.resumed_by_itself += arb.resumed_by_itself;
  if (mon.contact_us_on > 0) {
    ++tot.contact_sequences;
    tot.contact_seeds += fmt::format("    seed {}: last motion AM {} {} (main sensor {}), {}, body point ({:.0f}, {:.0f}) mm\n",
                                     seed, mon.contact_motion.left, mon.contact_motion.right,
                                     emergency::main_sensor(mon.contact_motion.left, mon.contact_motion.right, 600),
                                     mon.contact_while_stopping ? "while stopping" : "while moving",
                                     mon.contact_point.x() * 1000.0, mon.contact_point.y() * 1000.0);
  }
  const bool broke = mon.latched_moving > 0 || mon.ungranted > 0 || (contacts_fail && mon.contact_us_on > 0) ||
                     !arb.first.empty();
  if (!broke) return;
  report = fmt::format("seed {} (rule {}, map {}, noise {}, mask {}, latch {}, comm {} ticks, auto-toggle {}, motion time-out {} ms): {}\n"
                       "  latched-moving {}, ungranted {} (longest {} ticks), contact with sonar on {}\n"
                       "  commands: {}\n  world:\n{}",
                       seed, cfg.emergency.rule, map_kind_name(map_kind), opt.sonar_model != sim::SonarPreset::ideal, cfg.emergency.mask, cfg.emergency.latch, cfg.emergency.comm_limit_ticks,
                       cfg.emergency.auto_toggle, cfg.emergency.motion_timeout_ms,
                       mon.first_violation.empty() ? arb.first : mon.first_violation,
                       mon.latched_moving, mon.ungranted, mon.longest_disagreement, mon.contact_us_on, log, toml);
}

// Runs this shard's sequences (or only ROBUTER_SAFETY_SIM_SEED, in shard 0), prints the figures
// and returns the totals; failing sequences are reported (the first three in full).
Totals run_shard(int shard, bool contacts_fail) {
  const int total = total_sequences();
  Totals tot;
  int failures = 0;
  std::vector<std::uint64_t> seeds;
  if (const char* only = std::getenv("ROBUTER_SAFETY_SIM_SEED")) {
    if (shard == 0) seeds.push_back(std::strtoull(only, nullptr, 10));
  } else {
    for (int s = shard; s < total; s += kShards) seeds.push_back(static_cast<std::uint64_t>(s) + 1);
  }
  for (const std::uint64_t seed : seeds) {
    std::string report;
    run_sequence(seed, tot, report, contacts_fail);
    if (!report.empty() && ++failures <= 3) ADD_FAILURE() << report;
  }
  std::printf("shard %d/%d (rule %s): %ld sequences (%ld with sonar and odometry noise), %ld ticks (%.0f simulated s), "
              "%ld commands + %ld stop bytes, %ld unanswered, %ld protective stops, worst emergency activation %.0f us\n",
              shard + 1, kShards, rule_under_test().c_str(), tot.sequences, tot.noisy, tot.ticks,
              static_cast<double>(tot.ticks) / 100.0, tot.commands, tot.stop_bytes, tot.no_reply, tot.protective_stops,
              tot.emergency_max_us);
  std::printf("  a-priori maps: exact %ld, shifted %ld, another world's %ld; echo-arc cells narrowed out %ld\n",
              tot.mapped[1], tot.mapped[2], tot.mapped[3], tot.narrowed_cells);
  std::printf("  ticks moving %ld, latched %ld, sonar on %ld; trips %ld:", tot.moving_ticks, tot.latched_ticks,
              tot.us_on_ticks, tot.trips);
  for (std::size_t c = 1; c < tot.trips_by_cause.size(); ++c) {
    const std::string_view cause = word(static_cast<EmergencyCause>(c));
    if (tot.trips_by_cause[c]) std::printf(" %.*s %ld", static_cast<int>(cause.size()), cause.data(), tot.trips_by_cause[c]);
  }
  std::printf("\n  speed at the drive while latched: %ld ticks; drive behind the gate's verdict: %ld ticks "
              "(longest %ld)\n",
              tot.latched_moving, tot.ungranted, tot.longest_disagreement);
  std::printf("  arbiter: %ld automatic starts acknowledged, %ld ticks driven by an automatic mode; after an "
              "operator's command or a trip: %ld ticks; operator motions resumed by themselves: %ld ticks\n",
              tot.automatic_starts, tot.automatic_ticks, tot.automatic_after_operator, tot.resumed_by_itself);
  std::printf("  contacts with the sonar off (allowed): %ld ticks; sequences with a contact while the sonar watched: "
              "%ld; closest approach with the sonar on %.0f mm\n%s",
              tot.contacts_us_off, tot.contact_sequences, tot.min_clearance_us_on * 1000.0, tot.contact_seeds.c_str());
  EXPECT_EQ(failures, 0) << failures << " sequences broke an invariant";
  EXPECT_EQ(tot.no_reply, 0) << "every line is answered";
  EXPECT_GE(tot.sequences, static_cast<long>(seeds.size()) * 9 / 10) << "most seeds must give a valid world";
  return tot;
}

class RandomSequences : public testing::TestWithParam<int> {};

// The gate's invariants, strict, on every tick of every sequence: no non-zero speed reaches the
// drive while the emergency is latched; the drive never runs at a speed the gate does not grant
// now (a new verdict reaches it in the tick it is made — before kernel commit 595b67f a command
// taken between ticks could wait up to one executor period, and a verdict beyond the kernel's
// trigger bound waited for the executor's next period: this test found both); no automatic mode
// drives after an operator's command; nothing resumes by itself; and issue #13's criterion, no
// contact while the ultrasonic detection is on. Runs the default obstacle rule (the envelope;
// ROBUTER_EMERGENCY_RULE=seed for the seed's, which fails the contact criterion: docs/SAFETY.md
// §12 lists its seeds).
TEST_P(RandomSequences, NoContactWhileTheSonarWatchesNoSpeedWhileLatched) {
  const Totals tot = run_shard(GetParam(), true);
  EXPECT_EQ(tot.latched_moving, 0);
  EXPECT_EQ(tot.ungranted, 0);
  EXPECT_EQ(tot.automatic_after_operator, 0);
  EXPECT_EQ(tot.resumed_by_itself, 0);
  EXPECT_EQ(tot.contact_sequences, 0);
  EXPECT_GT(tot.automatic_starts, 0) << "the sequences start automatic modes";
  RecordProperty("automatic_after_operator_ticks", static_cast<int>(tot.automatic_after_operator));
  RecordProperty("resumed_by_itself_ticks", static_cast<int>(tot.resumed_by_itself));
  RecordProperty("sequences", static_cast<int>(tot.sequences));
  RecordProperty("ticks", static_cast<int>(tot.ticks));
  RecordProperty("trips", static_cast<int>(tot.trips));
  RecordProperty("protective_stops", static_cast<int>(tot.protective_stops));
  RecordProperty("latched_moving_ticks", static_cast<int>(tot.latched_moving));
  RecordProperty("drive_behind_gate_ticks", static_cast<int>(tot.ungranted));
  RecordProperty("contact_sequences", static_cast<int>(tot.contact_sequences));
}

INSTANTIATE_TEST_SUITE_P(Shards, RandomSequences, testing::Range(0, kShards));

// The eight sequences of the first 10,000-sequence bench that touched with the ultrasonic
// detection on: each set the odometry (AC) while at rest against a box inside the blanking range,
// which reset the evidence grid; the start pose's creep then touched the box (docs/SAFETY.md §13).
TEST(RandomSequencesFound, AnOdometrySetNextToABoxForgetsNothing) {
  Totals tot;
  for (const std::uint64_t seed : {2602u, 3145u, 3758u, 3776u, 3930u, 4788u, 6381u, 6777u}) {
    std::string report;
    run_sequence(seed, tot, report, true);
    EXPECT_TRUE(report.empty()) << report;
  }
  EXPECT_EQ(tot.contact_sequences, 0);
  EXPECT_EQ(tot.latched_moving, 0);
  EXPECT_EQ(tot.ungranted, 0);
}

}  // namespace
}  // namespace robuter::test::safety_sim
