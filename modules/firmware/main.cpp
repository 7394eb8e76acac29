// SPDX-License-Identifier: GPL-3.0-or-later
// robuterd: parses the command line and configuration, composes the firmware and runs it.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>

#include "cli/parse_or_usage.hpp"
#include "kernel/config.hpp"
#include "kernel/log.hpp"
#include "kernel/memory_usage.hpp"
#include "kernel/realtime.hpp"
#include "kernel/signals.hpp"
#include "modules/firmware/firmware.hpp"
#include "modules/notify/notify_socket.hpp"

namespace {
constexpr int kExitOk = 0;       // clean stop
constexpr int kExitRuntime = 1;  // a module could not start
constexpr int kExitUsage = 2;    // bad command line, configuration or world

// An installed robuterd takes its default world from its own prefix (<bindir>/../share/robuterd,
// wherever the prefix is); a build-tree one finds none there and keeps the source tree's.
std::string installed_default_world() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const auto world = (exe.parent_path() / ROBUTER_BIN_TO_DATA / "worlds" / "default.toml").lexically_normal();
  return std::filesystem::is_regular_file(world, ec) ? world.string() : std::string{};
}
}  // namespace

int main(int argc, char** argv) {
  using namespace robuter;
  CLI::App app{"robuterd — command server firmware for a Robuter differential-drive robot"};
  std::string config_path, log_level, speed = "1", sonar_model = "realistic";
  bool sonar_noise = false;
  bool stats = false, check_only = false, version = false, no_ptu = false;
  FirmwareOptions opt;
  app.add_option("-c,--config", config_path, "robot configuration file (TOML); defaults are the seed's constants");
  app.add_flag("--sim", opt.sim, "run on the simulated robot (SITL)");
  app.add_option("--world", opt.sim_options.world_file, "simulated world (.toml project format or seed-000 .env); default: the lab");
  app.add_option("--speed", speed, "simulation speed: N simulated seconds per second, or 'max'");
  app.add_option("--seed", opt.sim_options.seed, "seed of every random source of the simulator");
  app.add_flag("--odometry-noise", opt.sim_options.odometry_noise, "simulate encoder noise and wheel slip");
  CLI::Option* model_opt = app.add_option("--sonar-model", sonar_model, "simulator: the sonars' model: ideal, stress or realistic (docs/SIMULATOR.md); a configuration's [sim.sonar] keys still apply after it")
                               ->capture_default_str();
  app.add_flag("--sonar-noise", sonar_noise, "simulator: the same as --sonar-model stress (the project's first noise: range noise, drop-outs, spurious short echoes)");
  app.add_option("--pty", opt.ptys, "serve a link on a new pty; PATH becomes a symbolic link to it (repeatable)");
  app.add_option("--serial", opt.serial_device, "serve a link on a serial device (overrides [links.serial] device; re-opened when it comes back)");
  app.add_option("--baud", opt.baud, "serial link rate, bit/s (overrides [links.serial] baud, default 9600)");
  app.add_flag("--stdio", opt.stdio, "serve a link on standard input/output");
  app.add_option("--ptu-pty", opt.ptu_pty, "serve the simulated pan-tilt unit (PTU-46 protocol) on a new pty; PATH becomes a symbolic link to it");
  app.add_option("--ptu-port", opt.ptu_port, "the pan-tilt unit's serial device for the PTU module (overrides [ptu] port); with --sim, the --ptu-pty path");
  app.add_flag("--no-ptu", no_ptu, "simulator: the robot without its pan-tilt unit (by default the simulated unit is wired to the PTU module inside the process)");
  app.add_flag("--ptu-sweep", opt.ptu_sweep, "simulator: sweep the pan-tilt between its limits and fire its two sonars every 5° (no PTU module needed)");
  app.add_option("--picture", opt.picture, "simulator: at exit, draw world, robot, trail and the last ring ranges to FILE (.png, .svg or .pdf), with title, axes, scale bar and legend");
  app.add_option("--planner-pictures", opt.planner_pictures,
                 "write a PNG of every plan (map, expanded obstacles, path) into DIR, from a thread outside the kernel");
  app.add_flag("--stats", stats, "print per-process statistics and tick lateness at exit");
  app.add_option("--ticks", opt.ticks, "stop after this many ticks (0: run until stopped)");
  app.add_option("--log-level", log_level, "debug, info, warn, error or off (overrides the configuration)");
  app.add_flag("--check-config", check_only, "validate the configuration and exit");
  app.add_flag("--version", version, "print the version and exit");
  if (const auto status = cli::parse_or_usage(app, argc, argv)) return *status;  // kExitOk or kExitUsage
  if (version) {
    fmt::print("robuterd {}\n", ROBUTER_VERSION);
    return kExitOk;
  }
  opt.sim_ptu = !no_ptu;
  if (sonar_noise && model_opt->count() > 0) {
    fmt::print(stderr, "robuterd: --sonar-noise is --sonar-model stress: give one of them\n");
    return kExitUsage;
  }
  if (sonar_noise) sonar_model = "stress";
  if (const auto preset = sim::sonar_preset(sonar_model)) {
    opt.sim_options.sonar_model = *preset;
  } else {
    fmt::print(stderr, "robuterd: --sonar-model '{}': expected {}\n", sonar_model, sim::sonar_preset_choices());
    return kExitUsage;
  }
  if (speed == "max") {
    opt.speed = 0.0;
  } else {
    char* end = nullptr;
    opt.speed = std::strtod(speed.c_str(), &end);
    if (end == speed.c_str() || *end != '\0' || !(opt.speed > 0.0) || opt.speed > 1e6) {
      fmt::print(stderr, "robuterd: --speed '{}': expected a positive number or 'max'\n", speed);
      return kExitUsage;
    }
  }

  // Tests of the fatal-signal path: ROBUTERD_TEST_RAISE=SIGNAL:TICK (e.g. 11:50) raises SIGNAL from
  // the periodic path at TICK, as a crashing module would.
  if (const char* raise_at = std::getenv("ROBUTERD_TEST_RAISE")) {
    int sig = 0;
    unsigned long long tick = 0;
    if (std::sscanf(raise_at, "%d:%llu", &sig, &tick) != 2 || sig <= 0 || sig >= 32) {
      fmt::print(stderr, "robuterd: ROBUTERD_TEST_RAISE '{}': expected SIGNAL:TICK, e.g. 11:50\n", raise_at);
      return kExitUsage;
    }
    opt.test_raise_signal = sig;
    opt.test_raise_tick = tick;
  }

  // systemd (Type=notify, WatchdogSec=): READY=1 and WATCHDOG=1 from the periodic path.
  const NotifyEnvironment notify = notify_environment();
  opt.notify_socket = notify.socket;
  opt.watchdog_usec = notify.watchdog_usec;

  Config cfg;
  if (!config_path.empty()) {
    if (auto err = load_config(config_path, cfg)) {
      fmt::print(stderr, "robuterd: configuration error: {}\n", err->message());
      return kExitUsage;
    }
  }
  const std::string& level_text = log_level.empty() ? cfg.kernel.log_level : log_level;
  const std::optional<log::Level> level = from_word<log::Level>(level_text);
  if (!level) {
    fmt::print(stderr, "robuterd: --log-level '{}': expected debug, info, warn, error or off\n", level_text);
    return kExitUsage;
  }
  log::set_level(*level);
  if (check_only) opt.notify_socket.clear();  // ExecStartPre= is not the service's main process
  if (check_only) opt.sim = true;  // validate the table as the simulator would compose it
  if (check_only) opt.open_devices = false;  // a robot's configuration checks on any machine
  if (opt.sim && opt.sim_options.world_file.empty()) opt.sim_options.world_file = installed_default_world();

  // Start-up: everything is allocated here, before the periodic path runs.
  Firmware fw(cfg, opt);
  if (auto err = fw.setup()) {
    fmt::print(stderr, "robuterd: {}\n", *err);
    return kExitUsage;
  }
  if (check_only) {
    const std::string& map = fw.planner_map_note();
    const std::string& places = fw.places_note();
    fmt::print("robuterd: configuration {} is valid ({} processes){}{}{}{}\n", cfg.source, fw.kernel().process_count(),
               map.empty() ? "" : "; ", map, places.empty() ? "" : "; place graph ", places);
    return kExitOk;
  }
  for (std::size_t i = 0; i < opt.ptys.size(); ++i) {
    fmt::print("robuterd: link on {} -> {}\n", opt.ptys[i], fw.pty_slaves()[i]);
  }
  if (!opt.ptu_pty.empty()) fmt::print("robuterd: pan-tilt unit on {}\n", opt.ptu_pty);
  std::fflush(stdout);

  log::start(stderr);
  apply_realtime(cfg.kernel);
  Kernel::install_signal_handlers();
  log::info("robuterd {} starting: tick {} µs, {} processes{}", ROBUTER_VERSION, cfg.kernel.tick_us,
            fw.kernel().process_count(), opt.sim ? ", simulated robot" : "");
  if (opt.sim) {
    log::info("sim: world {}", opt.sim_options.world_file.empty() ? std::string("built-in default (source tree)")
                                                                   : opt.sim_options.world_file);
    log::info("sim: sonar model {} (--sonar-model; [sim.sonar] keys adjust it), seed {}",
              sim::sonar_preset_name(opt.sim_options.sonar_model), opt.sim_options.seed);
    // A log line, not stdout: with --stdio standard output is the command link.
    if (fw.ptu_pipe() != nullptr) log::info("sim: pan-tilt unit simulated in-process (--no-ptu: without it)");
  }
  const int status = fw.run();
  if (const int sig = signals::stop_signal()) log::info("robuterd: {} received: stopped cleanly", signals::name(sig));
  log::info("robuterd stopped after {} ticks", fw.kernel().tick());
  log::stop();
  if (stats) {
    fw.kernel().print_stats(stdout);
    if (const auto kb = peak_rss_kb()) fmt::print("peak memory (VmHWM) {} kB\n", *kb);
  }
  return status == 0 ? kExitOk : kExitRuntime;
}
