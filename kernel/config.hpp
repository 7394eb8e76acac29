// SPDX-License-Identifier: GPL-3.0-or-later
// The robot's configuration: one TOML file, defaults equal to the seed's constants.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hal/linux/can/can_params.hpp"
#include "hal/linux/gpio_params.hpp"
#include "kernel/kernel_params.hpp"
#include "kernel/param.hpp"
#include "modules/demo/demo_params.hpp"
#include "modules/doors/doors_params.hpp"
#include "modules/emergency/emergency_params.hpp"
#include "modules/gate/gate_params.hpp"
#include "modules/localise/localise_params.hpp"
#include "modules/places/places_params.hpp"
#include "modules/planner/planner_params.hpp"
#include "modules/ptu/ptu_params.hpp"
#include "modules/serial/serial_params.hpp"
#include "modules/us/sonar_params.hpp"
#include "robot/robot_model.hpp"
#include "robot/robot_params.hpp"

namespace robuter {

// Overrides of one row of the process table, by process name.
struct ProcessOverride {
  std::string name;                        // process name (must exist in the table)
  std::optional<std::uint32_t> period;     // ticks
  std::optional<std::uint32_t> offset;     // ticks
  std::optional<int> priority;             // higher runs first within a tick
  std::optional<std::uint32_t> budget_us;  // µs
  int line = 0;                            // line of its table in the file, for errors
  int period_line = 0;                     // line of its period key (0: not given), for errors
  int offset_line = 0;                     // line of its offset key
  int budget_line = 0;                     // line of its budget_us key
};

struct SimSection;  // kernel/sim_section.hpp

struct Config {
  std::string source = "(defaults)";         // file the configuration came from
  KernelConfig kernel;
  RobotConfig robot;
  SonarConfig sonar;
  EmergencyConfig emergency;
  PermissionsConfig permissions;
  PlannerModuleConfig planner;
  PlacesConfig places;                       // [places]
  LocaliseConfig localise;                   // [localise]
  PanTiltConfig ptu;
  GateConfig gate;
  DoorsConfig doors;
  LinksConfig links;                         // [links.serial]
  GpioConfig gpio;                           // [hardware.gpio]
  DemoConfig demo;
  HardwareConfig hardware;                   // [hardware] drive, sonar
  CanConfig can;                             // [can]
  std::vector<ProcessOverride> processes;    // [process.NAME] tables
  std::optional<std::vector<std::string>> enabled_modules;  // [modules] enabled; none = all
  std::shared_ptr<const SimSection> sim;     // [sim]: the simulated robot's own parameters, null when absent
};

// Every section's parameter table with the part of `c` it fills, in binding order:
// f(section name, table, part). The configuration reader binds through it; the tests that keep
// docs/CONFIG.md and config/robuterd.toml in step with the tables walk it too.
template <typename C, typename F>
void for_each_param_section(C& c, F&& f) {
  f(std::string_view("kernel"), kernel_params(), c.kernel);
  f(std::string_view("robot"), robot_params(), c.robot);
  f(std::string_view("sonar"), sonar_params(), c.sonar);
  f(std::string_view("emergency"), emergency_params(), c.emergency);
  f(std::string_view("permissions"), permissions_params(), c.permissions);
  f(std::string_view("planner"), planner_params(), c.planner);
  f(std::string_view("places"), places_params(), c.places);
  f(std::string_view("localise"), localise_params(), c.localise);
  f(std::string_view("ptu"), pan_tilt_params(), c.ptu);
  f(std::string_view("gate"), gate_params(), c.gate);
  f(std::string_view("doors"), doors_params(), c.doors);
  f(std::string_view("links"), links_params(), c.links);
  f(std::string_view("links.serial"), serial_link_params(), c.links.serial);
  f(std::string_view("hardware.gpio"), gpio_params(), c.gpio);
  f(std::string_view("demo"), demo_params(), c.demo);
  f(std::string_view("hardware"), hardware_params(), c.hardware);
  f(std::string_view("can"), can_params(), c.can);
}

// A configuration problem: where and what.
struct ConfigError {
  std::string file;   // path of the file
  int line = 0;       // 1-based line, 0 when not tied to one
  std::string key;    // dotted key, empty when not tied to one
  std::string what;   // the problem, for people
  // "file:line: key 'a.b': what".
  std::string message() const;
};

// The robot model the configuration describes: robot::kRobuter with [robot]'s body and wheels and
// [ptu]'s mount (pivot_x_mm, box_width_mm, beam_half_angle_centideg).
robot::RobotModel robot_model(const Config& c);

// Loads and validates a configuration file; the first problem found is returned.
std::optional<ConfigError> load_config(const std::string& path, Config& out);
// Parses configuration text (the file name is used in errors only).
std::optional<ConfigError> parse_config(std::string_view text, const std::string& file, Config& out);

}  // namespace robuter
