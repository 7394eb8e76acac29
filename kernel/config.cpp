// SPDX-License-Identifier: GPL-3.0-or-later
// Reads the configuration with toml++ and checks every key against the schema.
#include "kernel/config.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <span>
#include <type_traits>
#include <variant>
#include <sstream>
#include <toml++/toml.h>

#include "kernel/input_file.hpp"
#include "kernel/log.hpp"
#include "kernel/sim_section.hpp"

namespace robuter {

std::string ConfigError::message() const {
  std::string s = file;
  if (line > 0) s += fmt::format(":{}", line);
  s += ": ";
  if (!key.empty()) s += fmt::format("key '{}': ", key);
  return s + what;
}

namespace {

// Serial rates a port may be set to, bit/s (hal/linux/serial_settings.cpp).
constexpr std::uint32_t kSerialRates[] = {1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600};

// Binds TOML keys to config fields, remembering which keys were known so the rest can be
// reported as unknown. Stops at the first error.
class Binder {
 public:
  Binder(const std::string& file, const toml::table& root) : file_(file), root_(root) {}

  const std::optional<ConfigError>& error() const { return error_; }
  const std::string& file() const { return file_; }
  // The line of `key` in the file, 0 when it is not written.
  int line_of(const std::string& key) const {
    const toml::node* n = root_.at_path(key).node();
    return n ? static_cast<int>(n->source().begin.line) : 0;
  }

  // An integer key within [lo, hi].
  template <typename T>
  void integer(const std::string& key, T& out, long long lo, long long hi) {
    const toml::node* n = lookup(key);
    if (!n || error_) return;
    const auto* v = n->as_integer();
    if (!v) return fail(*n, key, fmt::format("expected an integer, got {}", type_name(*n)));
    const long long x = v->get();
    if (x < lo || x > hi) return fail(*n, key, fmt::format("{} is out of range {}..{}", x, lo, hi));
    out = static_cast<T>(x);
  }
  template <typename T>
  void integer(const std::string& key, std::optional<T>& out, long long lo, long long hi) {
    if (!lookup(key)) return;
    T v{};
    integer(key, v, lo, hi);
    if (!error_) out = v;
  }
  void boolean(const std::string& key, bool& out) {
    const toml::node* n = lookup(key);
    if (!n || error_) return;
    const auto* v = n->as_boolean();
    if (!v) return fail(*n, key, fmt::format("expected true or false, got {}", type_name(*n)));
    out = v->get();
  }
  // A string key, one of `choices` ('|'-separated) when they are given.
  void string(const std::string& key, std::string& out, std::string_view choices = {}) {
    const toml::node* n = lookup(key);
    if (!n || error_) return;
    const auto* v = n->as_string();
    if (!v) return fail(*n, key, fmt::format("expected a string, got {}", type_name(*n)));
    if (!choices.empty()) {
      bool ok = false;
      std::string list;
      for (std::string_view rest = choices; !rest.empty();) {
        const std::size_t bar = rest.find('|');
        const std::string_view c = rest.substr(0, bar);
        ok = ok || v->get() == c;
        list += list.empty() ? std::string(c) : fmt::format(", {}", c);
        rest = bar == std::string_view::npos ? std::string_view{} : rest.substr(bar + 1);
      }
      if (!ok) return fail(*n, key, fmt::format("'{}' is not one of: {}", v->get(), list));
    }
    out = v->get();
  }
  // An array of integers, each within [lo, hi] (GPIO line offsets).
  void integers(const std::string& key, std::vector<std::uint32_t>& out, long long lo, long long hi) {
    const toml::node* n = lookup(key);
    if (!n || error_) return;
    const auto* a = n->as_array();
    if (!a) return fail(*n, key, "expected an array of line offsets (integers)");
    out.clear();
    for (const auto& e : *a) {
      const auto* v = e.as_integer();
      if (!v || v->get() < lo || v->get() > hi)
        return fail(*n, key, fmt::format("expected line offsets, integers {}..{}", lo, hi));
      out.push_back(static_cast<std::uint32_t>(v->get()));
    }
  }
  void strings(const std::string& key, std::vector<std::string>& out) {
    const toml::node* n = lookup(key);
    if (!n || error_) return;
    const auto* a = n->as_array();
    if (!a) return fail(*n, key, fmt::format("expected an array of strings, got {}", type_name(*n)));
    out.clear();
    for (const auto& e : *a) {
      if (!e.is_string()) return fail(e, key, fmt::format("expected strings only, found {}", type_name(e)));
      out.push_back(e.as_string()->get());
    }
  }
  // Marks a table as known (its own keys are bound separately).
  void table(const std::string& key) {
    known_.insert(key);
    tables_.insert(key);
  }

  // Marks a table as known and leaves its contents to their owner (not walked for unknown keys).
  void foreign(const std::string& key) {
    table(key);
    foreign_.insert(key);
  }

  // Marks `key` as known and returns its node (null when absent), for keys checked by hand.
  const toml::node* claim(const std::string& key) { return lookup(key); }

  // Reports the first key in the file that no binding claimed.
  void reject_unknown() { walk(root_, ""); }

  // Records a validation failure tied to `key`.
  void fail_key(const std::string& key, const std::string& what) {
    const toml::node* n = root_.at_path(key).node();
    if (n) fail(*n, key, what);
    else if (!error_) error_ = ConfigError{file_, 0, key, what};
  }

 private:
  const toml::node* lookup(const std::string& key) {
    known_.insert(key);
    return root_.at_path(key).node();
  }
  static std::string type_name(const toml::node& n) {
    switch (n.type()) {
      case toml::node_type::string: return "a string";
      case toml::node_type::integer: return "an integer";
      case toml::node_type::floating_point: return "a number with a fraction";
      case toml::node_type::boolean: return "a boolean";
      case toml::node_type::array: return "an array";
      case toml::node_type::table: return "a table";
      default: return "a date or time";
    }
  }
  void fail(const toml::node& n, const std::string& key, const std::string& what) {
    if (!error_) error_ = ConfigError{file_, static_cast<int>(n.source().begin.line), key, what};
  }
  void walk(const toml::table& t, const std::string& prefix) {
    for (const auto& [k, v] : t) {
      if (error_) return;
      const std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
      if (!known_.count(key)) {
        error_ = ConfigError{file_, static_cast<int>(k.source().begin.line), key, "unknown key"};
        return;
      }
      if (const auto* sub = v.as_table()) {
        if (!foreign_.count(key)) walk(*sub, key);
      } else if (tables_.count(key)) {
        error_ = ConfigError{file_, static_cast<int>(k.source().begin.line), key,
                             fmt::format("expected a table, got {}", type_name(v))};
        return;
      }
    }
  }

  const std::string& file_;
  const toml::table& root_;
  std::set<std::string> known_;   // keys the schema bound
  std::set<std::string> tables_;  // keys that must be tables
  std::set<std::string> foreign_; // tables whose keys their owner checks
  std::optional<ConfigError> error_;
};

// The line rate of a serial port is one the device can be set to (hal/linux/serial_settings.cpp;
// kept equal by a unit test); `prefix` is its section.
void check_serial_rate(Binder& b, const std::string& prefix, std::uint32_t baud) {
  bool rate_ok = false;
  for (const std::uint32_t r : kSerialRates) rate_ok = rate_ok || r == baud;
  if (!rate_ok)
    b.fail_key(prefix + ".baud", fmt::format("{} is not a serial rate (1200, 2400, 4800, 9600, 19200, 38400, "
                                             "57600, 115200, 230400, 460800, 921600)", baud));
}

// Binds one section's keys by its module's table (kernel/param.hpp).
template <typename S, std::size_t N>
void bind_params(Binder& b, std::string_view section, std::span<const param::Param<S>, N> table, S& out) {
  b.table(std::string(section));
  for (const param::Param<S>& p : table) {
    const std::string key = fmt::format("{}.{}", section, p.key);
    std::visit(
        [&](auto field) {
          using F = std::remove_cvref_t<decltype(out.*field)>;
          if constexpr (std::is_same_v<F, bool>) b.boolean(key, out.*field);
          else if constexpr (std::is_integral_v<F>) b.integer(key, out.*field, p.lo, p.hi);
          else if constexpr (std::is_same_v<F, std::string>) b.string(key, out.*field, p.choices);
          else if constexpr (std::is_same_v<F, std::vector<std::string>>) b.strings(key, out.*field);
          else b.integers(key, out.*field, p.lo, p.hi);
        },
        p.field);
  }
}

// [hardware.gpio]: bumpers and digital inputs on a GPIO chip. Offsets must be distinct (one
// request holds each line once) and at most 32 in all (GPIO_V2_LINES_MAX is 64; the bumper mask
// is 32 bits).
void check_gpio(Binder& b, GpioConfig& g) {
  g.line = b.line_of("hardware.gpio.chip");
  std::vector<std::uint32_t> all = g.bumper_lines;
  all.insert(all.end(), g.input_lines.begin(), g.input_lines.end());
  if (all.size() > 32) return b.fail_key("hardware.gpio.input_lines", "more than 32 lines in all");
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (all[i] == all[j])
        return b.fail_key(i < g.bumper_lines.size() ? "hardware.gpio.bumper_lines" : "hardware.gpio.input_lines",
                          fmt::format("line {} is listed twice", all[i]));
  if (!g.chip.empty() && all.empty())
    return b.fail_key("hardware.gpio.chip", "a chip but no hardware.gpio.bumper_lines or input_lines");
  if (g.chip.empty() && !all.empty())
    return b.fail_key(g.bumper_lines.empty() ? "hardware.gpio.input_lines" : "hardware.gpio.bumper_lines",
                      "lines given but no hardware.gpio.chip");
}

// The [planner] section, and the map's size against what the planner can hold in memory.
void check_planner(Binder& b, PlannerModuleConfig& p) {
  if (p.initial_count >= p.hit_threshold)
    return b.fail_key("planner.initial_count", fmt::format("{} must be less than planner.hit_threshold {} (a first miss "
                                                           "would make a cell an obstacle)", p.initial_count, p.hit_threshold));
  // Decided: a relative map_file is relative to the configuration file's folder (as a unit
  // file's paths are to nothing in particular, the configuration travels with its map).
  if (!p.map_file.empty()) {
    p.map_file_line = b.line_of("planner.map_file");
    const std::filesystem::path f(p.map_file);
    if (f.is_relative()) p.map_file = (std::filesystem::path(b.file()).parent_path() / f).lexically_normal().string();
    const char* keys[] = {"planner.map_origin_x_mm", "planner.map_origin_y_mm", "planner.map_width_mm",
                          "planner.map_height_mm", "planner.cell_mm"};
    for (std::size_t i = 0; i < p.geometry_lines.size(); ++i) p.geometry_lines[i] = b.line_of(keys[i]);
    return;  // the map's size is checked against the file's header (modules/planner/prior_map.cpp)
  }
  const long long cells = static_cast<long long>(p.map_width_mm / p.cell_mm) * (p.map_height_mm / p.cell_mm);
  const long long limit = planner_cell_limit(p);
  if (cells > limit)
    b.fail_key("planner.map_width_mm", fmt::format("a map of {} cells is too large for the {} planner (at most {})",
                                                   cells, p.footprint, limit));
}

// The [hardware] and [can] sections (docs/CAN.md).
void check_can(Binder& b, CanConfig& c) {
  constexpr std::string_view kUnix = "unix:";  // a bus between processes (docs/CAN.md, robuter-can-nodes)
  if (c.interface.rfind(kUnix, 0) == 0) {
    if (c.interface.size() <= kUnix.size() || c.interface[kUnix.size()] != '/' || c.interface.size() - kUnix.size() > 107)
      return b.fail_key("can.interface", "expected unix:/absolute/path of at most 107 bytes");
  } else if (c.interface.empty() || c.interface.size() >= 16) {
    return b.fail_key("can.interface", "expected an interface name of 1 to 15 characters, or unix:/path");
  }
  if (c.left_node == c.right_node)
    return b.fail_key("can.right_node", fmt::format("{} is also can.left_node", c.right_node));
  for (const std::uint32_t id : {c.left_node, c.right_node})
    if (id >= c.sonar_node_base && id <= c.sonar_node_base + 7)
      return b.fail_key("can.sonar_node_base",
                        fmt::format("ultrasonic nodes {}..{} overlap drive node {}", c.sonar_node_base,
                                    c.sonar_node_base + 7, id));
  for (const std::uint32_t id : {c.left_node, c.right_node})
    if (id == c.host_node) return b.fail_key("can.host_node", fmt::format("{} is also a drive's node id", id));
  if (c.host_node >= c.sonar_node_base && c.host_node <= c.sonar_node_base + 7)
    return b.fail_key("can.host_node", fmt::format("{} is within the ultrasonic nodes {}..{}", c.host_node,
                                                   c.sonar_node_base, c.sonar_node_base + 7));
  if (c.drive_watchdog_ms != 0 && c.drive_watchdog_ms <= c.host_heartbeat_ms)
    return b.fail_key("can.drive_watchdog_ms", fmt::format("{} must be longer than can.host_heartbeat_ms {} (or 0: off)",
                                                           c.drive_watchdog_ms, c.host_heartbeat_ms));
  if (c.heartbeat_timeout_ms <= c.heartbeat_ms)
    return b.fail_key("can.heartbeat_timeout_ms",
                      fmt::format("{} must be longer than can.heartbeat_ms {}", c.heartbeat_timeout_ms, c.heartbeat_ms));
}

// Why: [places] file, relative to the configuration's folder like planner.map_file.
void check_places(Binder& b, PlacesConfig& p) {
  if (p.load_grids && p.grids_dir.empty()) return b.fail_key("places.load_grids", "needs places.grids_dir (the folder the grids are read from)");
  if (p.cross_doors && p.file.empty()) return b.fail_key("places.cross_doors", "needs places.file (the routes whose doors are crossed)");
  const std::filesystem::path folder = std::filesystem::path(b.file()).parent_path();
  if (!p.grids_dir.empty()) {
    if (p.file.empty()) return b.fail_key("places.grids_dir", "needs places.file (the places whose grids are saved)");
    const std::filesystem::path d(p.grids_dir);
    if (d.is_relative()) p.grids_dir = (folder / d).lexically_normal().string();
  }
  if (p.file.empty()) return;
  p.file_line = b.line_of("places.file");
  const std::filesystem::path f(p.file);
  if (f.is_relative()) p.file = (folder / f).lexically_normal().string();
}

// Why: [localise] needs a map to localise on; its state file is resolved like places.file.
void check_localise(Binder& b, LocaliseConfig& l, const PlannerModuleConfig& planner, const PlacesConfig& places) {
  if (l.min_particles > l.max_particles)
    return b.fail_key("localise.min_particles",
                      fmt::format("{} must not exceed localise.max_particles {}", l.min_particles, l.max_particles));
  if (l.enabled && planner.map_file.empty() && places.file.empty())
    return b.fail_key("localise.enabled", "needs a map: planner.map_file or places.file (its walls)");
  if (l.state_file.empty()) return;
  const std::filesystem::path f(l.state_file);
  if (f.is_relative()) l.state_file = (std::filesystem::path(b.file()).parent_path() / f).lexically_normal().string();
}

// Binds every section by its module's table, then checks the rules between keys.
void bind(Binder& b, const std::shared_ptr<const toml::table>& document, Config& c) {
  const toml::table& root = *document;
  for (const char* t : {"process", "modules"}) b.table(t);

  b.foreign("sim");  // the simulated robot's own parameters: hal/sitl checks them
  if (const toml::node* n = b.claim("sim"); n && n->is_table())
    c.sim = std::make_shared<const SimSection>(SimSection{document, n->as_table()});

  for_each_param_section(c, [&](std::string_view section, auto table, auto& part) { bind_params(b, section, table, part); });
  if (b.error()) return;

  if (c.robot.axle_to_front_mm >= c.robot.length_mm)
    return b.fail_key("robot.axle_to_front_mm", fmt::format("{} must be shorter than robot.length_mm {}",
                                                            c.robot.axle_to_front_mm, c.robot.length_mm));
  check_serial_rate(b, "links.serial", c.links.serial.baud);
  check_serial_rate(b, "ptu", c.ptu.baud);
  if (!b.error() && c.ptu.min_position >= c.ptu.max_position)
    b.fail_key("ptu.max_position", fmt::format("{} is not above ptu.min_position {}", c.ptu.max_position, c.ptu.min_position));
  if (b.error()) return;
  check_planner(b, c.planner);
  if (b.error()) return;
  check_places(b, c.places);
  if (b.error()) return;
  check_localise(b, c.localise, c.planner, c.places);
  if (b.error()) return;
  check_gpio(b, c.gpio);
  if (b.error()) return;
  check_can(b, c.can);

  if (root.at_path("modules.enabled").node()) {
    std::vector<std::string> names;
    b.strings("modules.enabled", names);
    c.enabled_modules = names;
  }

  if (const toml::node* p = root.at_path("process").node()) {
    const auto* procs = p->as_table();
    if (!procs) return b.fail_key("process", "expected a table of [process.NAME] tables");
    for (const auto& [name, node] : *procs) {
      const std::string key = "process." + std::string(name.str());
      if (!node.is_table()) return b.fail_key(key, "expected a table (period, offset, priority, budget_us)");
      b.table(key);
      ProcessOverride o;
      o.name = std::string(name.str());
      o.line = static_cast<int>(node.source().begin.line);
      b.integer(key + ".period", o.period, 1, 100'000);
      b.integer(key + ".offset", o.offset, 0, 100'000);
      b.integer(key + ".priority", o.priority, 0, 99);
      b.integer(key + ".budget_us", o.budget_us, 1, 100'000'000);
      const auto line_of = [&](const char* k) {
        const toml::node* n = root.at_path(key + "." + k).node();
        return n ? static_cast<int>(n->source().begin.line) : 0;
      };
      o.period_line = line_of("period");
      o.offset_line = line_of("offset");
      o.budget_line = line_of("budget_us");
      c.processes.push_back(o);
    }
  }
}

}  // namespace

// Memory per cell (docs/PLANNER.md): about 45 B per full-turn heading slice (2 x heading_slices:
// the body is not symmetric under a half turn) plus 60 B for the rectangle, 130 B for a disc;
// keep the planner within about 200 MB.
// Limits (docs/PLANNER.md "Limits"): a disc planner up to 1 M cells (~130 B each); a rectangle
// planner up to 512 x 512 cells: ~(2 x heading_slices + 4) B of layers and 4 B of turn bits
// per 16 slices + ~60 B per cell (about 26 MB at 16 slices) and, the tighter bound, its goal's
// cost field in one activation (the lab's 83,600 cells take 4-6 ms: 262,144 about 12-18 ms of
// the planner's 20 ms budget).
long long planner_cell_limit(const PlannerModuleConfig& p) { return p.footprint == "disc" ? 1'000'000 : 262'144; }

robot::RobotModel robot_model(const Config& c) {
  const auto m = [](std::int64_t v) { return static_cast<double>(v) / 1000.0; };
  robot::RobotModel r = robot::kRobuter;
  r.body.length = m(c.robot.length_mm);
  r.body.width = m(c.robot.width_mm);
  r.body.axle_to_front = m(c.robot.axle_to_front_mm);
  r.wheels.base = m(c.robot.wheel_base_mm);
  r.wheels.max_speed = c.robot.max_speed_cm_s / 100.0;
  r.wheels.max_accel = c.robot.max_accel_cm_s2 / 100.0;
  r.pan_tilt.pivot_x = m(c.ptu.pivot_x_mm);
  r.pan_tilt.face_offset = m(c.ptu.box_width_mm) / 2.0;
  r.pan_tilt.half_angle = c.ptu.beam_half_angle_centideg * robot::kDeg / 100.0;
  return r;
}

std::optional<ConfigError> parse_config(std::string_view text, const std::string& file, Config& out) {
  Config c;
  c.source = file;
  auto root = std::make_shared<toml::table>();
  try {
    *root = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    return ConfigError{file, static_cast<int>(e.source().begin.line), "", std::string(e.description())};
  }
  Binder b(file, *root);
  bind(b, root, c);
  if (!b.error()) b.reject_unknown();
  if (b.error()) return b.error();
  out = std::move(c);
  return std::nullopt;
}

std::optional<ConfigError> load_config(const std::string& path, Config& out) {
  std::string text;
  if (auto why = read_input_file(path, text)) return ConfigError{path, 0, "", *why};
  return parse_config(text, path, out);
}

}  // namespace robuter
