// robuterd: parses the command line and configuration, composes the modules and runs the kernel.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <memory>

#include "kernel/clock.hpp"
#include "kernel/config.hpp"
#include "kernel/kernel.hpp"
#include "kernel/log.hpp"
#include "kernel/realtime.hpp"
#include "modules/firmware/process_table.hpp"
#include "modules/heartbeat/heartbeat.hpp"
#include "modules/topics.hpp"

namespace {

constexpr int kExitOk = 0;       // clean stop
constexpr int kExitRuntime = 1;  // a module could not start
constexpr int kExitUsage = 2;    // bad command line or configuration

// Stops the kernel after a fixed number of ticks (--ticks), for scripts and measurements.
class TickLimit final : public robuter::Process {
 public:
  explicit TickLimit(std::uint64_t ticks) : ticks_(ticks) {}
  void run(robuter::Kernel& k) override {
    if (k.tick() + 1 >= ticks_) k.request_stop();
  }

 private:
  std::uint64_t ticks_;  // ticks to run, then stop
};

}  // namespace

int main(int argc, char** argv) {
  using namespace robuter;
  CLI::App app{"robuterd — command server firmware for a Robuter differential-drive robot"};
  std::string config_path;
  bool stats = false, check_only = false, version = false;
  std::uint64_t ticks = 0;
  std::string log_level;
  app.add_option("-c,--config", config_path, "robot configuration file (TOML); defaults are the seed's constants");
  app.add_flag("--stats", stats, "print per-process statistics and tick lateness at exit");
  app.add_option("--ticks", ticks, "stop after this many ticks (0: run until stopped)");
  app.add_option("--log-level", log_level, "debug, info, warn, error or off (overrides the configuration)");
  app.add_flag("--check-config", check_only, "validate the configuration and exit");
  app.add_flag("--version", version, "print the version and exit");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  }
  if (version) {
    fmt::print("robuterd {}\n", ROBUTER_VERSION);
    return kExitOk;
  }

  Config cfg;
  if (!config_path.empty()) {
    if (auto err = load_config(config_path, cfg)) {
      fmt::print(stderr, "robuterd: configuration error: {}\n", err->message());
      return kExitUsage;
    }
  }
  log::Level level{};
  const std::string& level_text = log_level.empty() ? cfg.kernel.log_level : log_level;
  if (!log::parse_level(level_text, level)) {
    fmt::print(stderr, "robuterd: --log-level '{}': expected debug, info, warn, error or off\n", level_text);
    return kExitUsage;
  }
  log::set_level(level);

  // Start-up: everything is allocated here, before the periodic path runs.
  static Blackboard bb;
  static HeartbeatModule heartbeat(bb);
  const NamedProcess modules[] = {{"heartbeat", &heartbeat}};
  std::vector<ProcessRow> table;
  if (auto err = build_table(cfg, modules, table)) {
    fmt::print(stderr, "robuterd: configuration error: {}\n", *err);
    return kExitUsage;
  }
  static TickLimit limit(ticks);
  if (ticks > 0) table.push_back(ProcessRow{"ticklimit", &limit, 1, 0, 0, 1000});

  RealClock clock;
  Kernel kernel(clock, static_cast<Nanos>(cfg.kernel.tick_us) * kNanosPerMicro);
  if (auto err = kernel.set_table(table)) {
    fmt::print(stderr, "robuterd: process table error: {}\n", *err);
    return kExitUsage;
  }
  if (check_only) {
    fmt::print("robuterd: configuration {} is valid ({} processes)\n", cfg.source, table.size());
    return kExitOk;
  }

  log::start(stderr);
  apply_realtime(cfg.kernel);
  Kernel::install_signal_handlers();
  log::info("robuterd {} starting: tick {} µs, {} processes", ROBUTER_VERSION, cfg.kernel.tick_us, table.size());
  const int status = kernel.run();
  log::info("robuterd stopped after {} ticks", kernel.tick());
  log::stop();
  if (stats) kernel.print_stats(stdout);
  return status == 0 ? kExitOk : kExitRuntime;
}
