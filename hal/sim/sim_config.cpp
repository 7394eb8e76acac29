// SPDX-License-Identifier: GPL-3.0-or-later
// TOML overrides of the simulator's configuration, strict like the world loader.
#include "hal/sim/sim_config.hpp"

#include "hal/sim/sonar_presets.hpp"
#include "hal/sim/toml_fields.hpp"

namespace robuter::sim {

namespace {

using detail::Fields;
using detail::ParseFailure;

// Assigns an optional value when present.
template <class T>
void maybe(T& field, const std::optional<double>& v) {
  if (v) field = static_cast<T>(*v);
}
void maybe(bool& field, const std::optional<bool>& v) {
  if (v) field = *v;
}

// Fails at the key's line when it is in the table, else at the table's line.
[[noreturn]] void fail_key(Fields& f, const char* key, const std::string& why) {
  if (const auto* n = f.get(key)) f.fail_at(*n, std::string(key) + ": " + why);
  f.fail(f.line(), std::string(key) + ": " + why);
}

// Refuses values that would make the model meaningless.
void positive(Fields& f, const char* key, double v) {
  if (!(v > 0.0)) fail_key(f, key, "must be positive");
}

// Refuses negative values (noises, tolerances, delays).
void non_negative(Fields& f, const char* key, double v) {
  if (v < 0.0) fail_key(f, key, "must not be negative");
}

// Refuses probabilities outside 0..1.
void probability(Fields& f, const char* key, double v) {
  if (v < 0.0 || v > 1.0) fail_key(f, key, "must be within 0..1");
}

// The sonar behaviour keys shared by [sonar] and [pan_tilt].
void read_sonar_params(Fields& f, SonarParams& p) {
  // The model first: the keys below may still change each of its effects.
  if (auto v = f.opt_string("model")) {
    const auto preset = sonar_preset(*v);
    if (!preset) f.fail_at(*f.get("model"), "model: expected " + std::string(sonar_preset_choices()));
    apply_sonar_preset(*preset, p);
  }
  if (auto v = f.opt_number("half_angle_deg")) {
    if (*v <= 0.0 || *v >= 89.0) f.fail_at(*f.get("half_angle_deg"), "half_angle_deg: must be within 0..89");
    p.half_angle = deg_to_rad(*v);
  }
  if (auto v = f.opt_number("timeout_ms")) {
    positive(f, "timeout_ms", *v);
    p.timeout = *v * 1e-3;
  }
  if (auto v = f.opt_number("sound_speed")) {
    positive(f, "sound_speed", *v);
    p.sound_speed = *v;
  }
  if (auto v = f.opt_number("min_range")) {
    non_negative(f, "min_range", *v);
    p.min_range = *v;
  }
  for (const auto& [key, field] : {std::pair{"max_incidence_deg", &SonarParams::max_incidence},
                                    std::pair{"max_incidence_smooth_deg", &SonarParams::max_incidence_smooth},
                                    std::pair{"max_incidence_rough_deg", &SonarParams::max_incidence_rough}}) {
    if (auto v = f.opt_number(key)) {
      if (*v < 0.0 || *v > 90.0) f.fail_at(*f.get(key), std::string(key) + ": must be within 0..90");
      p.*field = deg_to_rad(*v);
    }
  }
  if (auto v = f.opt_number("noise_sigma")) {
    non_negative(f, "noise_sigma", *v);
    p.noise_sigma = *v;
  }
  if (auto v = f.opt_number("noise_relative")) {
    non_negative(f, "noise_relative", *v);
    p.noise_relative = *v;
  }
  if (auto v = f.opt_number("spurious_probability")) {
    probability(f, "spurious_probability", *v);
    p.spurious_probability = *v;
  }
  if (auto v = f.opt_number("dropout_probability")) {
    probability(f, "dropout_probability", *v);
    p.dropout_probability = *v;
  }
  if (auto v = f.opt_number("scale")) {
    positive(f, "scale", *v);
    p.scale = *v;
  }
  maybe(p.multipath, f.opt_bool("multipath"));
  maybe(p.crosstalk, f.opt_bool("crosstalk"));
  maybe(p.spurious_in_window, f.opt_bool("spurious_in_window"));
  maybe(p.offset, f.opt_number("offset"));
  maybe(p.no_echo, f.opt_number("no_echo"));
}

// [robot]: geometry and drive; checks the result is a usable body.
void read_robot(Fields& f, RobotParams& r) {
  auto& g = r.geometry;
  maybe(g.length, f.opt_number("length"));
  maybe(g.width, f.opt_number("width"));
  maybe(g.axle_to_front, f.opt_number("axle_to_front"));
  maybe(g.wheel_base, f.opt_number("wheel_base"));
  maybe(r.limits.max_wheel_speed, f.opt_number("max_wheel_speed"));
  maybe(r.limits.max_accel, f.opt_number("max_accel"));
  maybe(r.limits.max_decel, f.opt_number("max_decel"));
  maybe(r.contact_tolerance, f.opt_number("contact_tolerance"));
  maybe(r.max_substep_travel, f.opt_number("max_substep_travel"));
  maybe(r.trail_spacing, f.opt_number("trail_spacing"));
  positive(f, "length", g.length);
  positive(f, "width", g.width);
  positive(f, "wheel_base", g.wheel_base);
  positive(f, "max_wheel_speed", r.limits.max_wheel_speed);
  non_negative(f, "max_accel", r.limits.max_accel);
  non_negative(f, "max_decel", r.limits.max_decel);
  non_negative(f, "contact_tolerance", r.contact_tolerance);
  positive(f, "max_substep_travel", r.max_substep_travel);
  if (g.axle_to_front <= 0.0 || g.axle_to_front >= g.length) {
    f.fail(f.line(), "axle_to_front must lie within the body length");
  }
  if (r.max_substep_travel >= std::min(g.length, g.width)) {
    f.fail(f.line(), "max_substep_travel must be smaller than the body, or walls could be jumped");
  }
}

// [odometry]: encoder and slip errors.
void read_odometry(Fields& f, OdometryErrors& o) {
  maybe(o.scale_left, f.opt_number("scale_left"));
  maybe(o.scale_right, f.opt_number("scale_right"));
  maybe(o.wheel_base_error, f.opt_number("wheel_base_error"));
  maybe(o.noise, f.opt_number("noise"));
  maybe(o.slip_mean, f.opt_number("slip_mean"));
  maybe(o.slip_sigma, f.opt_number("slip_sigma"));
  if (auto s = f.opt_integer("seed")) o.seed = static_cast<std::uint64_t>(*s);
  non_negative(f, "noise", o.noise);
  non_negative(f, "slip_sigma", o.slip_sigma);
}

// [[sonar.sensor]] rows replace fields of the numbered sensor.
void read_sensor(const toml::table& t, std::string_view file, const std::string& prefix, RingLayout& layout) {
  Fields f(t, file, "[[" + prefix + "sonar.sensor]]");
  const auto number = f.opt_integer("number");
  if (!number) f.fail(f.line(), "missing key 'number'");
  if (*number < 1 || *number > kRingSensors) {
    f.fail_at(*f.get("number"), "number: must be within 1..24");
  }
  f.set_what("[[" + prefix + "sonar.sensor]] " + std::to_string(*number));
  SonarMount& m = layout[static_cast<std::size_t>(*number - 1)];
  if (auto v = f.opt_number("x")) m.position.x() = *v;
  if (auto v = f.opt_number("y")) m.position.y() = *v;
  if (auto v = f.opt_number("direction_deg")) m.direction = wrap_angle(deg_to_rad(*v));
  f.finish();
}

// Applies each known section; throws ParseFailure on the first error.
// `prefix` names the tables in messages ("sim." when they sit in the firmware's configuration).
SimConfig apply(const toml::table& root, std::string_view file, SimConfig c, const std::string& prefix = "") {
  Fields top(root, file, prefix.empty() ? std::string("configuration") : "[" + prefix.substr(0, prefix.size() - 1) + "]");
  if (const auto* n = top.get("robot")) {
    if (!n->is_table()) top.fail_at(*n, "robot: expected a table [" + prefix + "robot]");
    Fields f(*n->as_table(), file, "[" + prefix + "robot]");
    read_robot(f, c.robot);
    f.finish();
  }
  if (const auto* n = top.get("odometry")) {
    if (!n->is_table()) top.fail_at(*n, "odometry: expected a table [" + prefix + "odometry]");
    Fields f(*n->as_table(), file, "[" + prefix + "odometry]");
    read_odometry(f, c.robot.odometry);
    f.finish();
  }
  if (const auto* n = top.get("sonar")) {
    if (!n->is_table()) top.fail_at(*n, "sonar: expected a table [" + prefix + "sonar]");
    Fields f(*n->as_table(), file, "[" + prefix + "sonar]");
    read_sonar_params(f, c.ring);
    c.timing.timeout = c.ring.timeout;
    if (auto v = f.opt_number("node_delay_ms")) {
      non_negative(f, "node_delay_ms", *v);
      c.timing.node_delay = *v * 1e-3;
    }
    if (auto s = f.opt_integer("seed")) c.sonar_seed = static_cast<std::uint64_t>(*s);
    if (const auto* s = f.get("sensor")) {
      if (!s->is_array_of_tables()) f.fail_at(*s, "sensor: must be written [[" + prefix + "sonar.sensor]]");
      for (const auto& row : *s->as_array()) read_sensor(*row.as_table(), file, prefix, c.layout);
    }
    f.finish();
  }
  if (const auto* n = top.get("pan_tilt")) {
    if (!n->is_table()) top.fail_at(*n, "pan_tilt: expected a table [" + prefix + "pan_tilt]");
    Fields f(*n->as_table(), file, "[" + prefix + "pan_tilt]");
    read_sonar_params(f, c.pan_tilt);
    if (auto v = f.opt_number("x")) c.pan_tilt_mount.pivot.x() = *v;
    if (auto v = f.opt_number("y")) c.pan_tilt_mount.pivot.y() = *v;
    if (auto v = f.opt_number("sensor_offset")) {
      non_negative(f, "sensor_offset", *v);
      c.pan_tilt_mount.sensor_offset = *v;
    }
    f.finish();
  }
  top.finish();
  return c;
}

}  // namespace

// Public entry points: the internal exception becomes an Error value here.
Result<SimConfig> apply_sim_config(const toml::table& table, std::string_view file,
                                   SimConfig base, std::string_view prefix) {
  try {
    return apply(table, file, std::move(base), std::string(prefix));
  } catch (const ParseFailure& e) {
    return e.error;
  }
}

// Parses first, then applies.
Result<SimConfig> parse_sim_config(std::string_view text, std::string_view file, SimConfig base) {
  try {
    return apply(detail::parse_toml(text, file), file, std::move(base));
  } catch (const ParseFailure& e) {
    return e.error;
  }
}

// Reads the whole file, then parses it.
Result<SimConfig> load_sim_config(const std::filesystem::path& path, SimConfig base) {
  std::string text;
  if (auto why = detail::read_text_file(path.string(), text)) return Error{path.string(), 0, *why};
  return parse_sim_config(text, path.string(), std::move(base));
}

}  // namespace robuter::sim
