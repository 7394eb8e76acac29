// SPDX-License-Identifier: GPL-3.0-or-later
// TOML overrides of the simulator's configuration, strict like the world loader.
#include "hal/sim/sim_config.hpp"

#include <initializer_list>

#include "hal/sim/sonar_presets.hpp"
#include "hal/sim/toml_fields.hpp"

namespace robuter::sim {

namespace {

using detail::Fields;
using detail::ParseFailure;

// Assigns an optional flag when present.
void maybe(bool& field, const std::optional<bool>& v) {
  if (v) field = *v;
}

// Fails at the key's line when it is in the table, else at the table's line.
[[noreturn]] void fail_key(Fields& f, const char* key, const std::string& why) {
  if (const auto* n = f.get(key)) f.fail_at(*n, std::string(key) + ": " + why);
  f.fail(f.line(), std::string(key) + ": " + why);
}

// A rule a number must pass, with the message when it does not.
struct Rule {
  bool (*ok)(double);  // true when the value passes
  const char* why;     // what the value must be, for the message
};
// Any finite value (the reader refuses the others).
constexpr Rule kAny{[](double) { return true; }, ""};
// Refuses values that would make the model meaningless.
constexpr Rule kPositive{[](double v) { return v > 0.0; }, "must be positive"};
// Refuses negative values (noises, tolerances, delays).
constexpr Rule kNonNegative{[](double v) { return v >= 0.0; }, "must not be negative"};
// Refuses probabilities outside 0..1.
constexpr Rule kProbability{[](double v) { return v >= 0.0 && v <= 1.0; }, "must be within 0..1"};
// A beam's half-angle: a cone that opens and does not look sideways, degrees.
constexpr Rule kHalfAngle{[](double v) { return v > 0.0 && v < 89.0; }, "must be within 0..89"};
// An incidence limit, degrees.
constexpr Rule kIncidence{[](double v) { return v >= 0.0 && v <= 90.0; }, "must be within 0..90"};

// Fails at `key` when `v` breaks `rule`.
void require(Fields& f, const char* key, double v, Rule rule) {
  if (!rule.ok(v)) fail_key(f, key, rule.why);
}

// Unit conversions from the file's words to the model's units.
double as_is(double v) { return v; }
double ms_to_s(double ms) { return ms * 1e-3; }

// Reads the optional number `key`: checked with `rule`, converted to the field's unit.
void read_number(Fields& f, const char* key, double& field, Rule rule, double (*convert)(double) = as_is) {
  if (auto v = f.opt_number(key)) {
    require(f, key, *v, rule);
    field = convert(*v);
  }
}

// The sonar behaviour keys shared by [sonar] and [pan_tilt].
void read_sonar_params(Fields& f, SonarParams& p) {
  // The model first: the keys below may still change each of its effects.
  if (auto v = f.opt_string("model")) {
    const auto preset = sonar_preset(*v);
    if (!preset) f.fail_at(*f.get("model"), "model: expected " + std::string(sonar_preset_choices()));
    apply_sonar_preset(*preset, p);
  }
  read_number(f, "half_angle_deg", p.half_angle, kHalfAngle, deg_to_rad);
  read_number(f, "timeout_ms", p.timeout, kPositive, ms_to_s);
  read_number(f, "sound_speed", p.sound_speed, kPositive);
  read_number(f, "min_range", p.min_range, kNonNegative);
  read_number(f, "max_incidence_deg", p.max_incidence, kIncidence, deg_to_rad);
  read_number(f, "max_incidence_smooth_deg", p.max_incidence_smooth, kIncidence, deg_to_rad);
  read_number(f, "max_incidence_rough_deg", p.max_incidence_rough, kIncidence, deg_to_rad);
  read_number(f, "noise_sigma", p.noise_sigma, kNonNegative);
  read_number(f, "noise_relative", p.noise_relative, kNonNegative);
  read_number(f, "spurious_probability", p.spurious_probability, kProbability);
  read_number(f, "dropout_probability", p.dropout_probability, kProbability);
  read_number(f, "scale", p.scale, kPositive);
  maybe(p.multipath, f.opt_bool("multipath"));
  maybe(p.crosstalk, f.opt_bool("crosstalk"));
  maybe(p.spurious_in_window, f.opt_bool("spurious_in_window"));
  read_number(f, "offset", p.offset, kAny);
  read_number(f, "no_echo", p.no_echo, kAny);
}

// A number key whose field is checked once the section is read, whether the file set it or the
// base configuration did.
struct CheckedKey {
  const char* key;  // key in the table
  double* field;    // where its value goes
  Rule rule;        // what the field must be after reading
};

// Reads every key of `keys` that is present (no checks yet).
void read_numbers(Fields& f, std::initializer_list<CheckedKey> keys) {
  for (const auto& k : keys) read_number(f, k.key, *k.field, kAny);
}

// Checks every field of `keys` against its rule, in order.
void check_numbers(Fields& f, std::initializer_list<CheckedKey> keys) {
  for (const auto& k : keys) require(f, k.key, *k.field, k.rule);
}

// [robot]: geometry and drive; checks the result is a usable body.
void read_robot(Fields& f, RobotParams& r) {
  auto& g = r.geometry;
  const std::initializer_list<CheckedKey> keys{
      {"length", &g.length, kPositive},
      {"width", &g.width, kPositive},
      {"axle_to_front", &g.axle_to_front, kAny},  // checked against the length below
      {"wheel_base", &g.wheel_base, kPositive},
      {"max_wheel_speed", &r.limits.max_wheel_speed, kPositive},
      {"max_accel", &r.limits.max_accel, kNonNegative},
      {"max_decel", &r.limits.max_decel, kNonNegative},
      {"contact_tolerance", &r.contact_tolerance, kNonNegative},
      {"max_substep_travel", &r.max_substep_travel, kPositive},
      {"trail_spacing", &r.trail_spacing, kAny}};
  read_numbers(f, keys);
  check_numbers(f, keys);
  if (g.axle_to_front <= 0.0 || g.axle_to_front >= g.length) {
    f.fail(f.line(), "axle_to_front must lie within the body length");
  }
  if (r.max_substep_travel >= std::min(g.length, g.width)) {
    f.fail(f.line(), "max_substep_travel must be smaller than the body, or walls could be jumped");
  }
}

// [odometry]: encoder and slip errors.
void read_odometry(Fields& f, OdometryErrors& o) {
  const std::initializer_list<CheckedKey> keys{
      {"scale_left", &o.scale_left, kAny},
      {"scale_right", &o.scale_right, kAny},
      {"wheel_base_error", &o.wheel_base_error, kAny},
      {"noise", &o.noise, kNonNegative},
      {"slip_mean", &o.slip_mean, kAny},
      {"slip_sigma", &o.slip_sigma, kNonNegative}};
  read_numbers(f, keys);
  if (auto s = f.opt_integer("seed")) o.seed = static_cast<std::uint64_t>(*s);
  check_numbers(f, keys);
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
  read_number(f, "x", m.position.x(), kAny);
  read_number(f, "y", m.position.y(), kAny);
  if (auto v = f.opt_number("direction_deg")) m.direction = wrap_angle(deg_to_rad(*v));
  f.finish();
}

// Reads the table `name` of `top` with `read` when it is there, then refuses its unknown keys.
template <class Read>
void read_section(Fields& top, const std::string& prefix, const char* name, Read read) {
  const auto* n = top.get(name);
  if (n == nullptr) return;
  const std::string title = "[" + prefix + name + "]";
  if (!n->is_table()) top.fail_at(*n, std::string(name) + ": expected a table " + title);
  Fields f(*n->as_table(), top.file(), title);
  read(f);
  f.finish();
}

// Applies each known section; throws ParseFailure on the first error.
// `prefix` names the tables in messages ("sim." when they sit in the firmware's configuration).
SimConfig apply(const toml::table& root, std::string_view file, SimConfig c, const std::string& prefix = "") {
  Fields top(root, file, prefix.empty() ? std::string("configuration") : "[" + prefix.substr(0, prefix.size() - 1) + "]");
  read_section(top, prefix, "robot", [&](Fields& f) { read_robot(f, c.robot); });
  read_section(top, prefix, "odometry", [&](Fields& f) { read_odometry(f, c.robot.odometry); });
  read_section(top, prefix, "sonar", [&](Fields& f) {
    read_sonar_params(f, c.ring);
    c.timing.timeout = c.ring.timeout;
    read_number(f, "node_delay_ms", c.timing.node_delay, kNonNegative, ms_to_s);
    if (auto s = f.opt_integer("seed")) c.sonar_seed = static_cast<std::uint64_t>(*s);
    if (const auto* s = f.get("sensor")) {
      if (!s->is_array_of_tables()) f.fail_at(*s, "sensor: must be written [[" + prefix + "sonar.sensor]]");
      for (const auto& row : *s->as_array()) read_sensor(*row.as_table(), file, prefix, c.layout);
    }
  });
  read_section(top, prefix, "pan_tilt", [&](Fields& f) {
    read_sonar_params(f, c.pan_tilt);
    read_number(f, "x", c.pan_tilt_mount.pivot.x(), kAny);
    read_number(f, "y", c.pan_tilt_mount.pivot.y(), kAny);
    read_number(f, "sensor_offset", c.pan_tilt_mount.sensor_offset, kNonNegative);
  });
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
