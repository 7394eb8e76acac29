// SPDX-License-Identifier: GPL-3.0-or-later
// Reads the configuration with toml++ and checks every key against the schema.
#include "kernel/config.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
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
  // A string key, optionally one of `choices`.
  void string(const std::string& key, std::string& out, std::initializer_list<const char*> choices = {}) {
    const toml::node* n = lookup(key);
    if (!n || error_) return;
    const auto* v = n->as_string();
    if (!v) return fail(*n, key, fmt::format("expected a string, got {}", type_name(*n)));
    if (choices.size()) {
      bool ok = false;
      std::string list;
      for (const char* c : choices) {
        ok = ok || v->get() == c;
        list += list.empty() ? c : fmt::format(", {}", c);
      }
      if (!ok) return fail(*n, key, fmt::format("'{}' is not one of: {}", v->get(), list));
    }
    out = v->get();
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

// Line settings of a serial port (docs/HARDWARE.md); `prefix` is its section. The rates are
// the ones hal/linux/serial_settings.cpp can set (kept equal by a unit test).
void bind_serial_line(Binder& b, const std::string& prefix, std::uint32_t& baud, std::string& parity,
                      std::uint32_t& stop_bits, std::string& flow, std::uint32_t& retry_ms) {
  b.integer(prefix + ".baud", baud, 1200, 921'600);
  bool rate_ok = false;
  for (const std::uint32_t r : kSerialRates) rate_ok = rate_ok || r == baud;
  if (!rate_ok)
    b.fail_key(prefix + ".baud", fmt::format("{} is not a serial rate (1200, 2400, 4800, 9600, 19200, 38400, "
                                             "57600, 115200, 230400, 460800, 921600)", baud));
  b.string(prefix + ".parity", parity, {"none", "even", "odd"});
  b.integer(prefix + ".stop_bits", stop_bits, 1, 2);
  b.string(prefix + ".flow_control", flow, {"none", "hardware", "software"});
  b.integer(prefix + ".retry_ms", retry_ms, 10, 60'000);
}

// [links.serial]: the serial command link.
void bind_links(Binder& b, LinksConfig& l) {
  b.boolean("links.stop_when_clients_leave", l.stop_when_clients_leave);
  b.table("links.serial");
  b.string("links.serial.device", l.serial.device);
  bind_serial_line(b, "links.serial", l.serial.baud, l.serial.parity, l.serial.stop_bits, l.serial.flow_control,
                   l.serial.retry_ms);
}

// [hardware.gpio]: bumpers and digital inputs on a GPIO chip. Offsets must be distinct (one
// request holds each line once) and at most 32 in all (GPIO_V2_LINES_MAX is 64; the bumper mask
// is 32 bits).
void bind_gpio(Binder& b, const toml::table& root, GpioConfig& g) {
  b.table("hardware.gpio");
  b.string("hardware.gpio.chip", g.chip);
  if (const toml::node* n = root.at_path("hardware.gpio.chip").node()) g.line = static_cast<int>(n->source().begin.line);
  b.boolean("hardware.gpio.active_low", g.active_low);
  b.integer("hardware.gpio.debounce_us", g.debounce_us, 0, 1'000'000);
  for (auto [key, out] : {std::pair{"hardware.gpio.bumper_lines", &g.bumper_lines},
                          std::pair{"hardware.gpio.input_lines", &g.input_lines}}) {
    const toml::node* n = b.claim(key);
    if (!n || b.error()) continue;
    const auto* a = n->as_array();
    if (!a) return b.fail_key(key, "expected an array of line offsets (integers)");
    out->clear();
    for (const auto& e : *a) {
      const auto* v = e.as_integer();
      if (!v || v->get() < 0 || v->get() > 1023)
        return b.fail_key(key, "expected line offsets, integers 0..1023");
      out->push_back(static_cast<std::uint32_t>(v->get()));
    }
  }
  if (b.error()) return;
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

// The [ptu], [gate] and [doors] sections (docs/DOORS.md): seed constants as defaults.
void bind_doors(Binder& b, PanTiltConfig& p, GateConfig& g, DoorsConfig& d) {
  b.string("ptu.port", p.port);
  bind_serial_line(b, "ptu", p.baud, p.parity, p.stop_bits, p.flow_control, p.retry_ms);
  b.integer("ptu.min_position", p.min_position, -100'000, 100'000);
  b.integer("ptu.max_position", p.max_position, -100'000, 100'000);
  b.integer("ptu.speed", p.speed, 1, 100'000);
  b.integer("ptu.acceleration", p.acceleration, 1, 1'000'000);
  b.integer("ptu.fire_tolerance_centideg", p.fire_tolerance_centideg, 1, 250);
  b.integer("ptu.poll_period_ticks", p.poll_period_ticks, 1, 1000);
  b.integer("ptu.reply_timeout_ticks", p.reply_timeout_ticks, 1, 10'000);
  b.integer("ptu.max_failures", p.max_failures, 1, 100);
  b.integer("ptu.cap_mm", p.cap_mm, 100, 20'000);
  b.integer("ptu.offset_mm", p.offset_mm, 0, 1000);
  b.integer("ptu.scale_permille", p.scale_permille, 500, 1500);
  b.integer("ptu.filter_high_mm", p.filter_high_mm, 0, 20'000);
  b.integer("ptu.filter_drop_mm", p.filter_drop_mm, 0, 20'000);
  b.integer("ptu.pivot_x_mm", p.pivot_x_mm, -5000, 5000);
  b.integer("ptu.box_width_mm", p.box_width_mm, 0, 1000);
  b.integer("ptu.beam_half_angle_centideg", p.beam_half_angle_centideg, 0, 4500);
  if (!b.error() && p.min_position >= p.max_position)
    b.fail_key("ptu.max_position", fmt::format("{} is not above ptu.min_position {}", p.max_position, p.min_position));

  b.integer("gate.margin_mm", g.margin_mm, 1, 10'000);
  b.integer("gate.max_gap_sectors", g.max_gap_sectors, 1, 36);
  b.integer("gate.min_mm", g.min_mm, 0, 10'000);
  b.integer("gate.max_mm", g.max_mm, 100, 20'000);
  b.integer("gate.speed_cm_s", g.speed_cm_s, 1, 100);
  b.integer("gate.turn_cm_s", g.turn_cm_s, 1, 100);
  b.integer("gate.timeout_ticks", g.timeout_ticks, 1, 1'000'000);
  b.integer("gate.stage_mm", g.stage_mm, 50, 5000);
  b.integer("gate.lateral_tolerance_mm", g.lateral_tolerance_mm, 1, 1000);
  b.integer("gate.heading_tolerance_centideg", g.heading_tolerance_centideg, 10, 3000);
  b.integer("gate.max_manoeuvres", g.max_manoeuvres, 1, 100);
  b.integer("gate.stall_ticks", g.stall_ticks, 50, 1'000'000);
  b.integer("gate.back_off_mm", g.back_off_mm, 0, 2000);
  b.boolean("gate.hand_over", g.hand_over);

  b.integer("doors.safety_mm", d.safety_mm, 0, 1000);
  b.integer("doors.max_dist_mm", d.max_dist_mm, 100, 20'000);
  b.integer("doors.time_before_move_ticks", d.time_before_move_ticks, 1, 1'000'000);
  b.integer("doors.forward_cm_s", d.forward_cm_s, 1, 100);
  b.integer("doors.back_cm_s", d.back_cm_s, 1, 100);
  b.integer("doors.entered_mm", d.entered_mm, 100, 20'000);
  b.integer("doors.beside_mm", d.beside_mm, 10, 20'000);
  b.integer("doors.exit_mm", d.exit_mm, 0, 10'000);
  b.integer("doors.max_age_ticks", d.max_age_ticks, 10, 1'000'000);
  b.integer("doors.same_echo_mm", d.same_echo_mm, 0, 1000);
  b.integer("doors.echo_spread_percent", d.echo_spread_percent, 0, 100);
  b.integer("doors.timeout_ticks", d.timeout_ticks, 0, 100'000'000);
  b.integer("doors.emergency_mask", d.emergency_mask, 0, 7);
}

// The [planner] section, and the map's size against what the planner can hold in memory.
void bind_planner(Binder& b, PlannerModuleConfig& p) {
  constexpr long long kFar = 1'000'000;  // mm: 1 km, beyond any room
  b.integer("planner.map_origin_x_mm", p.map_origin_x_mm, -kFar, kFar);
  b.integer("planner.map_origin_y_mm", p.map_origin_y_mm, -kFar, kFar);
  b.integer("planner.map_width_mm", p.map_width_mm, 500, kFar);
  b.integer("planner.map_height_mm", p.map_height_mm, 500, kFar);
  b.integer("planner.cell_mm", p.cell_mm, 10, 500);
  b.string("planner.footprint", p.footprint, {"rectangle", "disc"});
  b.integer("planner.disc_radius_mm", p.disc_radius_mm, 50, 5000);
  b.integer("planner.margin_mm", p.margin_mm, 0, 1000);
  b.integer("planner.turn_clearance_mm", p.turn_clearance_mm, 0, 1000);
  b.integer("planner.heading_slices", p.heading_slices, 4, 64);
  b.integer("planner.hit_threshold", p.hit_threshold, 1, 254);
  b.integer("planner.initial_count", p.initial_count, 0, 253);
  b.string("planner.map_file", p.map_file);
  b.integer("planner.scan_passes", p.scan_passes, 1, 20);
  b.integer("planner.beam_range_mm", p.beam_range_mm, 200, 10'000);
  b.integer("planner.beam_half_angle_centideg", p.beam_half_angle_centideg, 0, 4500);
  b.integer("planner.follow_range_mm", p.follow_range_mm, 100, 10'000);
  b.integer("planner.goal_tolerance_mm", p.goal_tolerance_mm, 10, 5000);
  b.integer("planner.drive_speed_cm_s", p.drive_speed_cm_s, 1, 100);
  b.integer("planner.turn_speed_cm_s", p.turn_speed_cm_s, 1, 100);
  if (b.error()) return;
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

// The [demo] section (docs/DOORS.md): the seed's dem.h constants as defaults.
void bind_demo(Binder& b, DemoConfig& d) {
  b.boolean("demo.enabled", d.enabled);
  b.integer("demo.distx_mm", d.distx_mm, 100, 10'000);
  b.integer("demo.disty_mm", d.disty_mm, 100, 10'000);
  b.integer("demo.raio_mm", d.raio_mm, 400, 10'000);
  b.integer("demo.straight_mm", d.straight_mm, 0, 100'000);
  b.integer("demo.lane_mm", d.lane_mm, 0, 100'000);
  b.integer("demo.speed_cm_s", d.speed_cm_s, 1, 100);
  b.integer("demo.slow_cm_s", d.slow_cm_s, 1, 100);
  b.integer("demo.align_cm_s", d.align_cm_s, 1, 100);
  b.integer("demo.sensor_a", d.sensor_a, 1, robot::kRingSensors);
  b.integer("demo.sensor_b", d.sensor_b, 1, robot::kRingSensors);
  b.integer("demo.front_sensor", d.front_sensor, 1, robot::kRingSensors);
  b.integer("demo.align_tolerance_mm", d.align_tolerance_mm, 1, 1000);
  b.integer("demo.calibration_readings", d.calibration_readings, 1, 9);  // demo::kMaxCalibrationReadings (asserted there)
  b.integer("demo.laps", d.laps, 0, 1'000'000);
  b.integer("demo.calibration_timeout_ticks", d.calibration_timeout_ticks, 0, 10'000'000);
}

// The [hardware] and [can] sections (docs/CAN.md).
void bind_can(Binder& b, HardwareConfig& h, CanConfig& c) {
  b.string("hardware.drive", h.drive, {"none", "can"});
  b.string("hardware.sonar", h.sonar, {"none", "can"});
  b.string("can.interface", c.interface);
  b.integer("can.left_node", c.left_node, 1, 127);
  b.integer("can.right_node", c.right_node, 1, 127);
  b.integer("can.sonar_node_base", c.sonar_node_base, 1, 120);
  b.integer("can.counts_per_rev", c.counts_per_rev, 1, 100'000'000);
  b.integer("can.wheel_diameter_mm", c.wheel_diameter_mm, 10, 5000);
  b.boolean("can.left_invert", c.left_invert);
  b.boolean("can.right_invert", c.right_invert);
  b.integer("can.heartbeat_ms", c.heartbeat_ms, 10, 10'000);
  b.integer("can.heartbeat_timeout_ms", c.heartbeat_timeout_ms, 20, 60'000);
  b.integer("can.sdo_timeout_ms", c.sdo_timeout_ms, 10, 10'000);
  b.integer("can.fault_reset_ms", c.fault_reset_ms, 10, 60'000);
  b.integer("can.host_node", c.host_node, 1, 127);
  b.integer("can.host_heartbeat_ms", c.host_heartbeat_ms, 10, 10'000);
  b.integer("can.drive_watchdog_ms", c.drive_watchdog_ms, 0, 60'000);
  if (b.error()) return;
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
void bind_places(Binder& b, PlacesConfig& p) {
  b.string("places.file", p.file);
  b.string("places.grids_dir", p.grids_dir);
  b.boolean("places.cross_doors", p.cross_doors);
  b.boolean("places.load_grids", p.load_grids);
  if (b.error()) return;
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
void bind_localise(Binder& b, LocaliseConfig& l, const PlannerModuleConfig& planner, const PlacesConfig& places) {
  constexpr long long kU32 = std::numeric_limits<std::uint32_t>::max();
  b.boolean("localise.enabled", l.enabled);
  // A step's motion and its resampling run whole in one activation: their work grows with
  // max_particles, so it is bounded at the 2,000 whose activations were measured (LOCALISATION.md).
  b.integer("localise.min_particles", l.min_particles, 10, 2'000);
  b.integer("localise.max_particles", l.max_particles, 10, 2'000);
  // The bounds on an activation's work, capped where it was measured under 2 ms (LOCALISATION.md,
  // "The module"): more would only let a setting break the bound.
  b.integer("localise.particles_per_run", l.particles_per_run, 10, 300);
  b.integer("localise.traces_per_run", l.traces_per_run, 10, 80);
  b.integer("localise.initial_sigma_mm", l.initial_sigma_mm, 0, 100'000);
  b.integer("localise.initial_sigma_deg", l.initial_sigma_deg, 0, 180);
  b.boolean("localise.report_corrected", l.report_corrected);
  b.string("localise.state_file", l.state_file);
  b.integer("localise.seed", l.seed, 0, kU32);
  if (b.error()) return;
  if (l.min_particles > l.max_particles)
    return b.fail_key("localise.min_particles",
                      fmt::format("{} must not exceed localise.max_particles {}", l.min_particles, l.max_particles));
  if (l.enabled && planner.map_file.empty() && places.file.empty())
    return b.fail_key("localise.enabled", "needs a map: planner.map_file or places.file (its walls)");
  if (l.state_file.empty()) return;
  const std::filesystem::path f(l.state_file);
  if (f.is_relative()) l.state_file = (std::filesystem::path(b.file()).parent_path() / f).lexically_normal().string();
}

// Binds every section of the schema.
void bind(Binder& b, const std::shared_ptr<const toml::table>& document, Config& c) {
  const toml::table& root = *document;
  constexpr long long kU32 = std::numeric_limits<std::uint32_t>::max();
  for (const char* t : {"kernel", "robot", "sonar", "emergency", "permissions", "planner", "ptu", "gate", "doors",
                        "demo", "process", "modules", "links", "hardware", "can", "places", "localise"})
    b.table(t);

  b.foreign("sim");  // the simulated robot's own parameters: hal/sitl checks them
  if (const toml::node* n = b.claim("sim"); n && n->is_table())
    c.sim = std::make_shared<const SimSection>(SimSection{document, n->as_table()});

  b.integer("kernel.tick_us", c.kernel.tick_us, 100, 1'000'000);
  b.boolean("kernel.realtime", c.kernel.realtime);
  b.integer("kernel.rt_priority", c.kernel.rt_priority, 1, 99);
  b.boolean("kernel.lock_memory", c.kernel.lock_memory);
  b.string("kernel.log_level", c.kernel.log_level, {"debug", "info", "warn", "error", "off"});

  b.integer("robot.length_mm", c.robot.length_mm, 100, 10'000);
  b.integer("robot.width_mm", c.robot.width_mm, 100, 10'000);
  b.integer("robot.axle_to_front_mm", c.robot.axle_to_front_mm, 1, 10'000);
  b.integer("robot.wheel_base_mm", c.robot.wheel_base_mm, 100, 10'000);
  b.integer("robot.max_speed_cm_s", c.robot.max_speed_cm_s, 1, 500);
  b.integer("robot.max_accel_cm_s2", c.robot.max_accel_cm_s2, 1, 10'000);
  b.integer("robot.max_decel_cm_s2", c.robot.max_decel_cm_s2, 1, 10'000);

  if (c.robot.axle_to_front_mm >= c.robot.length_mm)
    return b.fail_key("robot.axle_to_front_mm", fmt::format("{} must be shorter than robot.length_mm {}",
                                                            c.robot.axle_to_front_mm, c.robot.length_mm));

  b.integer("sonar.node_delay_ticks", c.sonar.node_delay_ticks, 0, 1000);
  b.integer("sonar.timeout_ms", c.sonar.timeout_ms, 1, 1000);
  b.integer("sonar.sound_speed_m_s", c.sonar.sound_speed_m_s, 200, 400);
  b.string("sonar.schedule", c.sonar.schedule, {"watch", "seed"});
  b.integer("sonar.moving_timeout_ms", c.sonar.moving_timeout_ms, 0, 1000);

  b.integer("emergency.mask", c.emergency.mask, 0, 7);
  b.integer("emergency.comm_limit_ticks", c.emergency.comm_limit_ticks, 1, kU32);
  b.integer("emergency.min_safety_mm", c.emergency.min_safety_mm, 0, 10'000);
  b.integer("emergency.safety_mm_per_cm_s", c.emergency.safety_mm_per_cm_s, 0, 1000);
  b.integer("emergency.motion_timeout_ms", c.emergency.motion_timeout_ms, 0, 3'600'000);
  b.boolean("emergency.auto_toggle", c.emergency.auto_toggle);
  b.boolean("emergency.latch", c.emergency.latch);
  b.string("emergency.rule", c.emergency.rule, {"envelope", "seed"});
  b.integer("emergency.margin_mm", c.emergency.margin_mm, 0, 500);
  b.integer("emergency.creep_cm_s", c.emergency.creep_cm_s, 0, 50);
  b.integer("emergency.free_age_ms", c.emergency.free_age_ms, 10, 600'000);
  b.integer("emergency.single_echo_ms", c.emergency.single_echo_ms, 0, 600'000);
  b.boolean("emergency.narrow_arcs", c.emergency.narrow_arcs);
  b.integer("emergency.protective_clear_ms", c.emergency.protective_clear_ms, 0, 600'000);
  b.integer("emergency.reaction_ms", c.emergency.reaction_ms, 0, 10'000);

  b.boolean("permissions.pass_through", c.permissions.pass_through);
  b.strings("permissions.pass_through_allow", c.permissions.pass_through_allow);
  b.boolean("permissions.shutdown", c.permissions.shutdown);

  bind_planner(b, c.planner);
  bind_places(b, c.places);
  bind_localise(b, c.localise, c.planner, c.places);
  bind_doors(b, c.ptu, c.gate, c.doors);
  bind_links(b, c.links);
  bind_gpio(b, root, c.gpio);
  bind_demo(b, c.demo);
  bind_can(b, c.hardware, c.can);

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
