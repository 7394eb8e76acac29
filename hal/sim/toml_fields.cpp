// SPDX-License-Identifier: GPL-3.0-or-later
// Strict TOML table reader: typed values, file:line errors, unknown-key rejection.
#include "hal/sim/toml_fields.hpp"

#include "kernel/input_file.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

namespace robuter::sim::detail {

int line_of(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

// Articles included so messages read naturally: "found a string".
std::string type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    default: return "nothing";
  }
}

// Keeps a reference to the table: it must outlive the reader.
Fields::Fields(const toml::table& table, std::string_view file, std::string what,
               double length_scale)
    : table_(table), file_(file), what_(std::move(what)), scale_(length_scale) {}

// Every key asked for becomes known, present or not, so finish() accepts it.
const toml::node* Fields::get(std::string_view key) {
  known_.emplace(key);
  return table_.get(key);
}

// All errors of a table read as "<what>: <message>".
void Fields::fail(int line, const std::string& message) const {
  throw ParseFailure{Error{file_, line, what_ + ": " + message}};
}

// Integers are numbers too; non-finite values are refused.
double Fields::as_number(const toml::node& node, std::string_view key) const {
  double v = 0.0;
  if (const auto* i = node.as_integer()) {
    v = static_cast<double>(i->get());
  } else if (const auto* f = node.as_floating_point()) {
    v = f->get();
  } else {
    fail_at(node, std::string(key) + ": expected a number, found " + type_name(node));
  }
  if (!std::isfinite(v)) fail_at(node, std::string(key) + ": not a finite number");
  return v;
}

// A point is an array of exactly two numbers.
Vec2 Fields::as_point(const toml::node& node, std::string_view key) const {
  const auto* arr = node.as_array();
  if (arr == nullptr || arr->size() != 2) {
    fail_at(node, std::string(key) + ": expected a point [x, y], found " +
                      (arr ? "an array of " + std::to_string(arr->size()) + " values"
                           : type_name(node)));
  }
  return {as_number(*arr->get(0), key) * scale_, as_number(*arr->get(1), key) * scale_};
}

double Fields::units() {
  const auto u = opt_string("units");
  if (!u || *u == "m") return 1.0;
  if (*u == "cm") return 0.01;
  if (*u == "mm") return 0.001;
  fail_at(*get("units"), "units: expected \"m\", \"cm\" or \"mm\", found \"" + *u + "\"");
}

// Required keys fail at the table's own line when missing.
const toml::node& Fields::required(std::string_view key) {
  const auto* n = get(key);
  if (n == nullptr) fail(line(), "missing key '" + std::string(key) + "'");
  return *n;
}

// Any other type is refused at the value's line.
template <class T>
std::optional<T> Fields::opt_value(std::string_view key, const char* expected) {
  const auto* n = get(key);
  if (n == nullptr) return std::nullopt;
  const auto* v = n->as<T>();
  if (v == nullptr) fail_at(*n, std::string(key) + ": expected " + expected + ", found " + type_name(*n));
  return v->get();
}

double Fields::number(std::string_view key) { return as_number(required(key), key); }

// Optional keys are empty when absent, checked when present.
std::optional<double> Fields::opt_number(std::string_view key) {
  const auto* n = get(key);
  if (n == nullptr) return std::nullopt;
  return as_number(*n, key);
}

double Fields::length(std::string_view key) { return number(key) * scale_; }

// A length in the file's units, returned in metres.
std::optional<double> Fields::opt_length(std::string_view key) {
  auto v = opt_number(key);
  if (v) *v *= scale_;
  return v;
}

// Whole numbers only (counts, seeds, indices).
std::optional<std::int64_t> Fields::opt_integer(std::string_view key) {
  return opt_value<std::int64_t>(key, "an integer");
}

// true or false, nothing else.
std::optional<bool> Fields::opt_bool(std::string_view key) { return opt_value<bool>(key, "true or false"); }

// A string, nothing else.
std::optional<std::string> Fields::opt_string(std::string_view key) {
  return opt_value<std::string>(key, "a string");
}

// An optional [x, y] in the file's units.
std::optional<Vec2> Fields::opt_point(std::string_view key) {
  const auto* n = get(key);
  if (n == nullptr) return std::nullopt;
  return as_point(*n, key);
}

// A required [x, y] in the file's units.
Vec2 Fields::point(std::string_view key) { return as_point(required(key), key); }

// An array of [x, y] points in the file's units.
std::vector<Vec2> Fields::points(std::string_view key) {
  const auto& n = required(key);
  const auto* arr = n.as_array();
  if (arr == nullptr) {
    fail_at(n, std::string(key) + ": expected an array of points, found " + type_name(n));
  }
  std::vector<Vec2> out;
  out.reserve(arr->size());
  for (const auto& p : *arr) out.push_back(as_point(p, key));
  return out;
}

// Keys are reported in file order so the first mistake is the one named.
void Fields::finish() const {
  const toml::key* first = nullptr;
  for (const auto& [k, v] : table_) {
    if (known_.find(k.str()) != known_.end()) continue;
    if (first == nullptr || k.source().begin.line < first->source().begin.line) first = &k;
  }
  if (first != nullptr) {
    fail(static_cast<int>(first->source().begin.line), "unknown key '" + std::string(first->str()) + "'");
  }
}

// toml++ throws parse_error; it becomes a ParseFailure with the same line.
toml::table parse_toml(std::string_view text, std::string_view file) {
  try {
    return toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw ParseFailure{Error{std::string(file), static_cast<int>(e.source().begin.line),
                             std::string(e.description())}};
  }
}

// Regular files of at most 1 MB (kernel/input_file.hpp); line ends are the parsers' business.
std::optional<std::string> read_text_file(const std::string& path, std::string& out) {
  return read_input_file(path, out);
}

}  // namespace robuter::sim::detail
