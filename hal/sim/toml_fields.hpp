// SPDX-License-Identifier: GPL-3.0-or-later
// Strict reading of TOML tables for the simulator's files: typed getters that report the file
// and line of a bad value, and rejection of keys nobody asked for. Internal to robuter_sim.
#pragma once

#include <toml++/toml.h>

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "hal/sim/result.hpp"
#include "hal/sim/types.hpp"

namespace robuter::sim::detail {

// Thrown inside parsers only; the public entry points catch it and return its Error.
struct ParseFailure {
  Error error;  // what to report
};

// Line where a node starts in its file (0 when unknown).
int line_of(const toml::node& node);

// A readable name for a node's type ("a string", "an array"...).
std::string type_name(const toml::node& node);

// Reads the keys of one table. Every getter marks its key as known; finish() then rejects any
// other key. Lengths are multiplied by `length_scale` (the file's units).
class Fields {
 public:
  Fields(const toml::table& table, std::string_view file, std::string what,
         double length_scale = 1.0);

  // The raw node for `key`, or null; marks the key as known.
  const toml::node* get(std::string_view key);

  double number(std::string_view key);                       // required number
  std::optional<double> opt_number(std::string_view key);    // optional number
  double length(std::string_view key);                       // required length, m
  std::optional<double> opt_length(std::string_view key);    // optional length, m
  std::optional<std::int64_t> opt_integer(std::string_view key);
  std::optional<bool> opt_bool(std::string_view key);
  std::optional<std::string> opt_string(std::string_view key);
  std::optional<Vec2> opt_point(std::string_view key);       // [x, y] lengths, m
  Vec2 point(std::string_view key);                          // required [x, y], m
  std::vector<Vec2> points(std::string_view key);            // required [[x, y], ...], m

  // Why: a file's length unit, one rule for every project TOML file: the key `units` ("m", "cm"
  // or "mm"), in metres per unit; 1 when absent.
  double units();

  // Throws for the first key (in file order) that no getter asked for.
  void finish() const;

  // Throws a ParseFailure at `line` with `message` prefixed by what this table is.
  [[noreturn]] void fail(int line, const std::string& message) const;
  [[noreturn]] void fail_at(const toml::node& node, const std::string& message) const {
    fail(line_of(node), message);
  }

  int line() const { return line_of(table_); }            // line of the table itself
  const std::string& what() const { return what_; }       // e.g. "[[wall]] 'north'"
  void set_what(std::string what) { what_ = std::move(what); }
  const std::string& file() const { return file_; }

 private:
  // The node of a required key; fails at the table's line when it is missing.
  const toml::node& required(std::string_view key);
  // An optional key of toml++ value type `T`; `expected` names that type in the message.
  template <class T>
  std::optional<T> opt_value(std::string_view key, const char* expected);
  double as_number(const toml::node& node, std::string_view key) const;
  Vec2 as_point(const toml::node& node, std::string_view key) const;

  const toml::table& table_;        // the table read
  std::string file_;                // file name for messages
  std::string what_;                // table description for messages
  double scale_;                    // file length unit, m
  std::set<std::string, std::less<>> known_;  // keys asked for
};

// Parses TOML text, turning toml++'s parse errors into ParseFailure with file and line.
toml::table parse_toml(std::string_view text, std::string_view file);

// Reads a whole file into `out` (a regular file of at most 1 MB); the reason when it cannot.
std::optional<std::string> read_text_file(const std::string& path, std::string& out);

}  // namespace robuter::sim::detail
