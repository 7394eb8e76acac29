// SPDX-License-Identifier: GPL-3.0-or-later
// The modules' parameter tables against what users read: every key with a doc and a range that
// holds its default; config/robuterd.toml listing every key at its default; docs/CONFIG.md's rows
// agreeing with the tables on unit, default and range (a test fails when they disagree).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "kernel/config.hpp"

namespace robuter {
namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// One key as its module's table declares it, flattened.
struct KeyInfo {
  std::string unit;      // the table's unit
  std::string def;       // the default (the field's initialiser), as text
  std::string range;     // "lo..hi" for integers, "a, b" for words, "" otherwise
  std::string doc;       // the table's one-line doc
  bool integer = false;  // an integer key
  long long lo = 0;      // its range
  long long hi = 0;
  long long value = 0;   // its default
  std::string choices;   // '|'-separated words
};

template <typename S, typename V>
void describe(V S::*field, const param::Param<S>& p, KeyInfo& k) {
  const S d{};
  const V& v = d.*field;
  if constexpr (std::is_same_v<V, bool>) {
    k.def = v ? "true" : "false";
  } else if constexpr (std::is_integral_v<V>) {
    k.integer = true;
    k.lo = p.lo;
    k.hi = p.hi;
    k.value = static_cast<long long>(v);
    k.def = std::to_string(v);
    k.range = fmt::format("{}..{}", p.lo, p.hi);
  } else if constexpr (std::is_same_v<V, std::string>) {
    k.def = v;
  } else {
    k.def = v.empty() ? "[]" : "(a list)";
    if constexpr (std::is_same_v<V, std::vector<std::uint32_t>>) k.range = fmt::format("{}..{}", p.lo, p.hi);
  }
}

std::map<std::string, KeyInfo> table_keys() {
  std::map<std::string, KeyInfo> out;
  const Config c;
  for_each_param_section(c, [&](std::string_view section, auto table, const auto&) {
    for (const auto& p : table) {
      KeyInfo k;
      k.unit = std::string(p.unit);
      k.doc = std::string(p.doc);
      k.choices = std::string(p.choices);
      std::visit([&](auto field) { describe(field, p, k); }, p.field);
      if (!p.choices.empty()) k.range = std::regex_replace(k.choices, std::regex("\\|"), ", ");
      out[fmt::format("{}.{}", section, p.key)] = k;
    }
  });
  return out;
}

// docs/CONFIG.md's text normalised for comparison: no backticks or quotes, ASCII minus, no
// thousands separators in numbers.
std::string plain(std::string s) {
  s = std::regex_replace(s, std::regex("[`\"]"), "");
  s = std::regex_replace(s, std::regex("−"), "-");
  for (const std::regex thousands("(\\d),(\\d{3})"); std::regex_search(s, thousands);)
    s = std::regex_replace(s, thousands, "$1$2");  // 1,000,000: each pass joins every other group
  return std::regex_replace(s, std::regex("^\\s+|\\s+$"), "");
}

std::vector<std::string> split(const std::string& s, const std::string& sep) {
  std::vector<std::string> out;
  std::size_t at = 0;
  for (std::size_t i; (i = s.find(sep, at)) != std::string::npos; at = i + sep.size()) out.push_back(s.substr(at, i - at));
  out.push_back(s.substr(at));
  return out;
}

// A row of one of docs/CONFIG.md's key tables, per key: its unit, default and range cells.
struct DocRow {
  std::string unit, def, range;
  int line = 0;
};

std::map<std::string, DocRow> config_md_rows() {
  std::map<std::string, DocRow> out;
  std::istringstream in(read_file(ROBUTER_SOURCE_DIR "/docs/CONFIG.md"));
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.rfind("| `", 0) != 0) continue;
    std::vector<std::string> cells = split(line.substr(1), "|");  // the cells between the bars
    if (cells.size() < 5) continue;
    for (std::string& c : cells) c = std::regex_replace(c, std::regex("^\\s+|\\s+$"), "");
    std::vector<std::string> keys = split(plain(cells[0]), ", ");
    const std::vector<std::string> units = split(cells[1], ", ");
    const std::vector<std::string> defs = split(cells[2], ", ");
    for (std::size_t i = 0; i < keys.size(); ++i) {
      DocRow r;
      r.unit = plain(units.size() == keys.size() ? units[i] : cells[1]);
      std::string d = plain(defs.size() == keys.size() ? defs[i] : cells[2]);
      d = std::regex_replace(d, std::regex("\\s*\\(.*\\)$"), "");  // "0 (off)", "\"\" (none)"
      r.def = d;
      r.range = plain(cells[3]);
      r.line = n;
      out[keys[i]] = r;
    }
  }
  return out;
}

// Every key says what it does, and its default is one its own range or words accept.
TEST(ConfigTables, EveryKeyHasADocAndItsDefaultIsInItsRange) {
  const auto keys = table_keys();
  EXPECT_GT(keys.size(), 150u);
  for (const auto& [key, k] : keys) {
    EXPECT_FALSE(k.doc.empty()) << key;
    if (k.integer) {
      EXPECT_LE(k.lo, k.hi) << key;
      EXPECT_GE(k.value, k.lo) << key;
      EXPECT_LE(k.value, k.hi) << key;
    }
    if (!k.choices.empty()) {
      EXPECT_NE(("|" + k.choices + "|").find("|" + k.def + "|"), std::string::npos) << key;
    }
  }
}

// docs/CONFIG.md has a row for every key of every table, with the table's unit, default and
// range; and no row for a key no table declares (the [process], [modules] and [sim] keys are the
// kernel's and the simulator's, documented apart).
TEST(ConfigTables, ConfigMdAgreesWithTheTables) {
  const auto keys = table_keys();
  const auto rows = config_md_rows();
  for (const auto& [key, k] : keys) {
    const auto it = rows.find(key);
    if (it == rows.end()) {
      ADD_FAILURE() << "docs/CONFIG.md has no row for " << key;
      continue;
    }
    const DocRow& r = it->second;
    EXPECT_EQ(r.unit, k.unit) << "docs/CONFIG.md:" << r.line << ": unit of " << key;
    EXPECT_EQ(r.def, k.def) << "docs/CONFIG.md:" << r.line << ": default of " << key;
    if (!k.range.empty()) {
      const bool symmetric = k.integer && k.lo == -k.hi && r.range.rfind(fmt::format("±{}", k.hi), 0) == 0;
      EXPECT_TRUE(r.range.rfind(k.range, 0) == 0 || symmetric)
          << "docs/CONFIG.md:" << r.line << ": range of " << key << " is '" << r.range << "', the table's " << k.range;
    }  // where the table has no range (booleans, free text), the cell may say what it wants
  }
  for (const auto& [key, r] : rows) {
    if (key.rfind("process.", 0) == 0 || key.rfind("modules.", 0) == 0 || key.rfind("sim.", 0) == 0 ||
        key.rfind("[[sim", 0) == 0)
      continue;
    EXPECT_TRUE(keys.count(key)) << "docs/CONFIG.md:" << r.line << ": " << key << " is in no module's table";
  }
}

// config/robuterd.toml names every key of every table, each at its default.
TEST(ConfigTables, TheShippedFileListsEveryKeyAtItsDefault) {
  const std::string path = ROBUTER_SOURCE_DIR "/config/robuterd.toml";
  Config c;
  const auto err = load_config(path, c);
  ASSERT_FALSE(err) << err->message();
  std::istringstream in(read_file(path));
  std::string line, section;
  std::set<std::string> written;
  const std::regex header(R"(^\[([\w.]+)\])"), assignment(R"(^#?\s*(\w+)\s*=)");
  for (std::smatch m; std::getline(in, line);) {
    if (std::regex_search(line, m, header)) section = m[1];
    else if (std::regex_search(line, m, assignment)) written.insert(section + "." + std::string(m[1]));
  }
  for_each_param_section(c, [&](std::string_view name, auto table, const auto& part) {
    const std::remove_cvref_t<decltype(part)> defaults{};  // the fields' initialisers
    for (const auto& p : table) {
      const std::string key = fmt::format("{}.{}", name, p.key);
      EXPECT_TRUE(written.count(key)) << "config/robuterd.toml does not list " << key;
      std::visit([&](auto field) { EXPECT_TRUE(part.*field == defaults.*field) << key << " is not at its default"; },
                 p.field);
    }
  });
}

}  // namespace
}  // namespace robuter
