// SPDX-License-Identifier: GPL-3.0-or-later
// Parsers for MovingAI .map and .scen files (CRLF tolerated, errors name file and line).
#include "modules/planner/lib/movingai.hpp"

#include "modules/planner/lib/text_reader.hpp"

namespace robuter::plan {
namespace {

bool blank(std::string_view line) { return split_words(line).empty(); }

}  // namespace

Result<OccupancyMap> parse_movingai_map(std::string_view text, const std::string& name) {
  const auto lines = split_lines(text);
  long long width = -1;
  long long height = -1;
  std::size_t i = 0;
  bool typed = false;
  // Header: "type octile", "height H", "width W", "map" (height and width in either order).
  for (; i < lines.size(); ++i) {
    const auto f = split_words(lines[i]);
    const int line = static_cast<int>(i) + 1;
    if (f.empty()) continue;
    if (f.size() == 1 && f[0] == "map") break;
    if (f.size() != 2) return Error{name, line, "malformed header line '" + std::string(lines[i]) + "'"};
    if (f[0] == "type") {
      if (f[1] != "octile") return Error{name, line, "unsupported map type '" + std::string(f[1]) + "'"};
      typed = true;
    } else if (f[0] == "height" || f[0] == "width") {
      const auto v = parse_integer(f[1]);
      if (!v || *v <= 0 || *v > 65535)
        return Error{name, line, "bad " + std::string(f[0]) + " '" + std::string(f[1]) + "'"};
      (f[0] == "height" ? height : width) = *v;
    } else {
      return Error{name, line, "unknown header key '" + std::string(f[0]) + "'"};
    }
  }
  if (i >= lines.size()) return Error{name, static_cast<int>(lines.size()), "no 'map' line"};
  if (!typed) return Error{name, 1, "missing 'type octile'"};
  if (width < 0 || height < 0) return Error{name, static_cast<int>(i) + 1, "missing width or height"};
  if (width * height > 16'000'000) return Error{name, static_cast<int>(i) + 1, "map too large (more than 16 million cells)"};
  ++i;
  OccupancyMap map(MapGeometry{static_cast<int>(width), static_cast<int>(height), 1.0, {}}, 1);
  for (int y = 0; y < height; ++y, ++i) {
    if (i >= lines.size())
      return Error{name, static_cast<int>(lines.size()),
                   "unexpected end of file: " + std::to_string(y) + " of " +
                       std::to_string(height) + " rows"};
    const std::string_view row = lines[i];
    if (static_cast<long long>(row.size()) != width)
      return Error{name, static_cast<int>(i) + 1,
                   "row has " + std::to_string(row.size()) + " cells, expected " +
                       std::to_string(width)};
    for (int x = 0; x < width; ++x) {
      const char c = row[static_cast<std::size_t>(x)];
      if (c == '.' || c == 'G' || c == 'S') map.mark_free({x, y});
      else map.mark_occupied({x, y});
    }
  }
  for (; i < lines.size(); ++i)
    if (!blank(lines[i])) return Error{name, static_cast<int>(i) + 1, "unexpected data after the map rows"};
  map.clear_changes();
  return map;
}

Result<OccupancyMap> load_movingai_map(const std::string& path) {
  return load_text_file(path, parse_movingai_map);
}

Result<std::vector<Scenario>> parse_movingai_scen(std::string_view text, const std::string& name) {
  const auto lines = split_lines(text);
  std::vector<Scenario> out;
  std::size_t i = 0;
  while (i < lines.size() && blank(lines[i])) ++i;
  if (i >= lines.size()) return Error{name, 1, "empty scenario file"};
  {
    const auto f = split_words(lines[i]);
    if (f.size() != 2 || f[0] != "version" || !parse_real(f[1]))
      return Error{name, static_cast<int>(i) + 1, "expected 'version N', got '" + std::string(lines[i]) + "'"};
    ++i;
  }
  for (; i < lines.size(); ++i) {
    const int line = static_cast<int>(i) + 1;
    const auto f = split_words(lines[i]);
    if (f.empty()) continue;
    if (f.size() != 9)
      return Error{name, line, "expected 9 fields, got " + std::to_string(f.size())};
    Scenario s;
    s.map = std::string(f[1]);
    long long v[7] = {};
    const std::size_t at[7] = {0, 2, 3, 4, 5, 6, 7};
    const char* what[7] = {"bucket", "map width", "map height", "start x", "start y", "goal x", "goal y"};
    for (int k = 0; k < 7; ++k) {
      const auto n = parse_integer(f[at[k]]);
      if (!n || *n < 0 || *n > 1'000'000)
        return Error{name, line, std::string("bad ") + what[k] + " '" + std::string(f[at[k]]) + "'"};
      v[k] = *n;
    }
    const auto opt = parse_real(f[8]);
    if (!opt || *opt < 0.0) return Error{name, line, "bad optimal length '" + std::string(f[8]) + "'"};
    s.bucket = static_cast<int>(v[0]);
    s.map_width = static_cast<int>(v[1]);
    s.map_height = static_cast<int>(v[2]);
    s.start = {static_cast<int>(v[3]), static_cast<int>(v[4])};
    s.goal = {static_cast<int>(v[5]), static_cast<int>(v[6])};
    s.optimal = *opt;
    out.push_back(std::move(s));
  }
  return out;
}

Result<std::vector<Scenario>> load_movingai_scen(const std::string& path) {
  return load_text_file(path, parse_movingai_scen);
}

}  // namespace robuter::plan
