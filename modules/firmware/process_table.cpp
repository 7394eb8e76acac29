// SPDX-License-Identifier: GPL-3.0-or-later
// Default process table and how configuration changes it.
#include "modules/firmware/process_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>

namespace robuter {

namespace {
// name, period, offset, priority, budget_us. Seed: read_sensors 4/6 prio 2, serial_spy 2/0
// prio 3, execute 10/2 prio 4, emergency 10/4 prio 5 (higher runs first in a shared tick).
constexpr DefaultRow kDefaults[] = {
    {"sim", 1, 0, 99, 5000},        // simulated world (SITL only): first in every tick
    {"can", 1, 0, 90, 2000},        // CAN bus (hardware only): frames in, drive/sonar supervision, RPDOs, SYNC
    {"serial", 2, 0, 3, 2000},      // command links (seed serial_spy 2, 3, 0)
    {"us", 1, 0, 2, 2000},          // ultrasonic ring (seed read_sensors 4, 2, 6): every tick, so a node is
                                    // read the tick its echoes are in and fired the tick its delay ends
    {"executor", 10, 2, 4, 2000},   // motors and odometry (seed execute 10, 4, 2)
    {"emergency", 10, 4, 5, 2000},  // watchdog and request-to-move gate (seed emergency 10, 5, 4)
    {"heartbeat", 100, 0, 1, 1000}, // proof of life, once a second
    {"planner", 10, 3, 0, 20000},   // grid planner: an odd tick (only "sim" runs there), last in it;
                                    // a plan may take ~10 ms (docs/PLANNER.md, "The module")
    {"ptu", 1, 0, 2, 1000},         // pan-tilt unit: polled every 30 ms (seed), each 5° firing at its nearest tick
    {"gate", 2, 1, 1, 2000},        // passage finder (AG/AT): manoeuvre control every 20 ms
    {"doors", 5, 3, 1, 2000},       // door crossing (Ad/Af): steering every 50 ms
    {"demo", 5, 4, 1, 1000},        // demonstration course ([demo] enabled): every 50 ms
    {"localise", 2, 1, 0, 2000},    // localisation ([localise] enabled): an odd tick, a filter step's part
                                    // of particles_per_run each 20 ms (docs/LOCALISATION.md, "The module")
};
}  // namespace

std::span<const DefaultRow> default_table() { return kDefaults; }

std::optional<std::string> build_table(const Config& cfg, std::span<const NamedProcess> modules,
                                       std::vector<ProcessRow>& out) {
  out.clear();
  auto known = [&](const std::string& n) {
    return std::any_of(std::begin(kDefaults), std::end(kDefaults), [&](const DefaultRow& r) { return n == r.name; });
  };
  auto known_list = [&] {
    std::string s;
    for (const auto& r : kDefaults) s += (s.empty() ? "" : ", ") + std::string(r.name);
    return s;
  };
  if (cfg.enabled_modules) {
    for (const auto& n : *cfg.enabled_modules)
      if (!known(n))
        return fmt::format("{}: key 'modules.enabled': no module named '{}' (known: {})", cfg.source, n, known_list());
  }
  for (const auto& o : cfg.processes)
    if (!known(o.name))
      return fmt::format("{}:{}: key 'process.{}': no process of that name (known: {})", cfg.source, o.line, o.name,
                         known_list());

  for (const DefaultRow& d : kDefaults) {
    if (cfg.enabled_modules &&
        std::find(cfg.enabled_modules->begin(), cfg.enabled_modules->end(), d.name) == cfg.enabled_modules->end())
      continue;
    ProcessRow r{d.name, nullptr, d.period, d.offset, d.priority, d.budget_us};
    for (const auto& m : modules)
      if (std::strcmp(m.name, d.name) == 0) r.process = m.process;
    if (r.process == nullptr) continue;  // not composed in this run (e.g. "sim" on hardware)
    const ProcessOverride* over = nullptr;
    for (const auto& o : cfg.processes) {
      if (o.name != d.name) continue;
      over = &o;
      if (o.period) r.period = *o.period;
      if (o.offset) r.offset = *o.offset;
      if (o.priority) r.priority = *o.priority;
      if (o.budget_us) r.budget_us = *o.budget_us;
    }
    // A default budget never exceeds its period: with a tick under 5 ms the "sim" row's 5000 µs
    // would (docs/CONFIG.md, kernel.tick_us); a budget given in the file is checked, not cut.
    const std::uint64_t period_us = static_cast<std::uint64_t>(r.period) * cfg.kernel.tick_us;
    if (!(over && over->budget_us) && r.budget_us > period_us) r.budget_us = static_cast<std::uint32_t>(period_us);
    if (over) {
      const auto at = [&](int line, const char* key, const std::string& what) {
        return fmt::format("{}:{}: key 'process.{}.{}': {}", cfg.source, line ? line : over->line, d.name, key, what);
      };
      if (r.offset >= r.period)
        return at(over->offset ? over->offset_line : over->period_line, over->offset ? "offset" : "period",
                  fmt::format("offset {} must be less than the period {}", r.offset, r.period));
      if (r.budget_us > period_us)
        return at(over->budget_us ? over->budget_line : over->period_line, over->budget_us ? "budget_us" : "period",
                  fmt::format("budget {} µs exceeds the period of {} µs ({} ticks of {} µs)", r.budget_us, period_us,
                              r.period, cfg.kernel.tick_us));
    }
    out.push_back(r);
  }
  return std::nullopt;
}

}  // namespace robuter
