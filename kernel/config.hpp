// The robot's configuration: one TOML file, defaults equal to the seed's constants.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace robuter {

// Kernel timing and real-time set-up.
struct KernelConfig {
  std::uint32_t tick_us = 10'000;   // tick length, µs (seed: 10 ms)
  bool realtime = false;            // ask for SCHED_FIFO at start-up
  int rt_priority = 50;             // SCHED_FIFO priority, 1..99
  bool lock_memory = false;         // mlockall(MCL_CURRENT | MCL_FUTURE) at start-up
  std::string log_level = "info";   // debug, info, warn, error, off
};

// Overrides of one row of the process table, by process name.
struct ProcessOverride {
  std::string name;                        // process name (must exist in the table)
  std::optional<std::uint32_t> period;     // ticks
  std::optional<std::uint32_t> offset;     // ticks
  std::optional<int> priority;             // higher runs first within a tick
  std::optional<std::uint32_t> budget_us;  // µs
  int line = 0;                            // line of its table in the file, for errors
};

// The Robuter's body (seed 002).
struct RobotConfig {
  std::uint32_t length_mm = 1025;        // rectangle length along x, mm
  std::uint32_t width_mm = 700;          // rectangle width, mm
  std::uint32_t wheel_base_mm = 600;     // distance between the drive wheels (DBW), mm
  std::uint32_t max_speed_cm_s = 100;    // largest wheel speed accepted, cm/s
  std::uint32_t max_accel_cm_s2 = 50;    // wheel acceleration limit, cm/s²
};

// Ultrasonic ring timing (us.c).
struct SonarConfig {
  std::uint32_t node_delay_ticks = 3;    // delay between firing two nodes, ticks
  std::uint32_t timeout_ms = 33;         // echo time-out, ms (≈ 5 m at 300 m/s)
  std::uint32_t sound_speed_m_s = 300;   // calibrated speed of sound, m/s
};

// Emergency watchdog (emerg.c).
struct EmergencyConfig {
  std::uint32_t mask = 7;                    // enabled detections: bumper 1, ultrasonic 2, communication 4
  std::uint32_t comm_limit_ticks = 18'000;   // link silence that trips, ticks (3 min)
  std::uint32_t min_safety_mm = 220;         // smallest safety distance, mm
  std::uint32_t safety_mm_per_cm_s = 10;     // safety distance per cm/s of the faster wheel, mm
  std::uint32_t motion_timeout_ms = 0;       // stop when no motion command for this long while moving; 0 = off
  bool auto_toggle = false;                  // only the watch-dog sensors fire
  bool latch = true;                         // a tripped emergency holds until re-enabled
};

// What operators may do over the link.
struct PermissionsConfig {
  bool pass_through = false;                 // AY accepted at all
  std::vector<std::string> pass_through_allow;  // AY command prefixes allowed when enabled
  bool shutdown = true;                      // AX accepted
};

struct Config {
  std::string source = "(defaults)";         // file the configuration came from
  KernelConfig kernel;
  RobotConfig robot;
  SonarConfig sonar;
  EmergencyConfig emergency;
  PermissionsConfig permissions;
  std::vector<ProcessOverride> processes;    // [process.NAME] tables
  std::optional<std::vector<std::string>> enabled_modules;  // [modules] enabled; none = all
};

// A configuration problem: where and what.
struct ConfigError {
  std::string file;   // path of the file
  int line = 0;       // 1-based line, 0 when not tied to one
  std::string key;    // dotted key, empty when not tied to one
  std::string what;   // the problem, for people
  // "file:line: key 'a.b': what".
  std::string message() const;
};

// Loads and validates a configuration file; the first problem found is returned.
std::optional<ConfigError> load_config(const std::string& path, Config& out);
// Parses configuration text (the file name is used in errors only).
std::optional<ConfigError> parse_config(std::string_view text, const std::string& file, Config& out);

}  // namespace robuter
