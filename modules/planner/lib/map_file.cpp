// SPDX-License-Identifier: GPL-3.0-or-later
// Writing and reading the "robuter-map 1" saved-map format.
#include "modules/planner/lib/map_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "modules/planner/lib/text_reader.hpp"

namespace robuter::plan {
namespace {

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

std::string format_map(const OccupancyMap& map) {
  const MapGeometry& g = map.geometry();
  std::string out;
  char buf[160];
  std::snprintf(buf, sizeof buf, "robuter-map 1\nwidth %d\nheight %d\nresolution %.17g\norigin %.17g %.17g\nthreshold %d\ndata\n",
                g.width, g.height, g.resolution, g.origin.x, g.origin.y, map.threshold());
  out += buf;
  static const char* hex = "0123456789abcdef";
  out.reserve(out.size() + static_cast<std::size_t>(g.height) * static_cast<std::size_t>(2 * g.width + 1));
  for (int y = g.height - 1; y >= 0; --y) {
    for (int x = 0; x < g.width; ++x) {
      const std::uint8_t n = map.count({x, y});
      if (n == OccupancyMap::kUnknown) {
        out += "..";
      } else {
        out += hex[n >> 4];
        out += hex[n & 15];
      }
    }
    out += '\n';
  }
  return out;
}

namespace {
// Why: one header reader for parse_map and parse_map_header; `i` ends on the "data" line's index.
Result<MapHeader> read_header(const std::vector<std::string_view>& lines, const std::string& name, std::size_t& i) {
  if (lines.empty() || split_words(lines[0]).size() != 2 || split_words(lines[0])[0] != "robuter-map")
    return Error{name, 1, "not a robuter map (expected 'robuter-map 1')"};
  if (split_words(lines[0])[1] != "1") return Error{name, 1, "unsupported robuter-map version '" + std::string(split_words(lines[0])[1]) + "'"};
  MapHeader h;
  MapGeometry& g = h.geometry;
  g = MapGeometry{-1, -1, -1.0, {}};
  i = 1;
  for (; i < lines.size(); ++i) {
    const int line = static_cast<int>(i) + 1;
    const auto w = split_words(lines[i]);
    if (w.empty() || w[0].front() == '#') continue;
    if (w[0] == "data" && w.size() == 1) break;
    auto need = [&](std::size_t n) { return w.size() == n + 1; };
    if (w[0] == "width" || w[0] == "height") {
      const auto v = need(1) ? parse_integer(w[1]) : std::nullopt;
      if (!v || *v <= 0 || *v > 100000) return Error{name, line, "bad " + std::string(w[0])};
      (w[0] == "width" ? g.width : g.height) = static_cast<int>(*v);
      (w[0] == "width" ? h.width_line : h.height_line) = line;
    } else if (w[0] == "resolution") {
      const auto v = need(1) ? parse_real(w[1]) : std::nullopt;
      if (!v || *v <= 0.0) return Error{name, line, "bad resolution"};
      g.resolution = *v;
      h.resolution_line = line;
    } else if (w[0] == "origin") {
      const auto x = need(2) ? parse_real(w[1]) : std::nullopt;
      const auto y = need(2) ? parse_real(w[2]) : std::nullopt;
      if (!x || !y) return Error{name, line, "bad origin (expected 'origin X Y')"};
      g.origin = {*x, *y};
      h.origin_line = line;
    } else if (w[0] == "threshold") {
      const auto v = need(1) ? parse_integer(w[1]) : std::nullopt;
      if (!v || *v < 1 || *v > OccupancyMap::kMaxCount) return Error{name, line, "bad threshold"};
      h.threshold = static_cast<int>(*v);
      h.threshold_line = line;
    } else {
      return Error{name, line, "unknown header key '" + std::string(w[0]) + "'"};
    }
  }
  if (i >= lines.size()) return Error{name, static_cast<int>(lines.size()), "no 'data' line"};
  h.data_line = static_cast<int>(i) + 1;
  if (g.width < 0 || g.height < 0 || g.resolution <= 0.0)
    return Error{name, static_cast<int>(i) + 1, "width, height and resolution must come before 'data'"};
  if (static_cast<long long>(g.width) * g.height > 16'000'000)
    return Error{name, static_cast<int>(i) + 1, "map too large (more than 16 million cells)"};
  return h;
}
}  // namespace

Result<MapHeader> parse_map_header(std::string_view text, const std::string& name) {
  std::size_t i = 0;
  return read_header(split_lines(text), name, i);
}

Result<OccupancyMap> parse_map(std::string_view text, const std::string& name) {
  const auto lines = split_lines(text);
  std::size_t i = 0;
  const auto header = read_header(lines, name, i);
  if (!header) return header.error();
  const MapGeometry& g = header->geometry;
  const int threshold = header->threshold;
  ++i;
  OccupancyMap map(g, static_cast<std::uint8_t>(threshold));
  for (int y = g.height - 1; y >= 0; --y, ++i) {
    if (i >= lines.size())
      return Error{name, static_cast<int>(lines.size()), "unexpected end of file: missing map rows"};
    const std::string_view row = lines[i];
    const int line = static_cast<int>(i) + 1;
    if (row.size() != static_cast<std::size_t>(2 * g.width))
      return Error{name, line, "row has " + std::to_string(row.size()) + " characters, expected " + std::to_string(2 * g.width)};
    for (int x = 0; x < g.width; ++x) {
      const char a = row[static_cast<std::size_t>(2 * x)];
      const char b = row[static_cast<std::size_t>(2 * x + 1)];
      if (a == '.' && b == '.') continue;
      const int hi = hex_value(a), lo = hex_value(b);
      if (hi < 0 || lo < 0 || hi * 16 + lo > OccupancyMap::kMaxCount)
        return Error{name, line, "bad cell '" + std::string{a, b} + "' at column " + std::to_string(x)};
      map.set_count({x, y}, static_cast<std::uint8_t>(hi * 16 + lo));
    }
  }
  for (; i < lines.size(); ++i)
    if (!split_words(lines[i]).empty()) return Error{name, static_cast<int>(i) + 1, "unexpected data after the map rows"};
  map.clear_changes();
  return map;
}

Status save_map(const OccupancyMap& map, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) return Error{path, 0, std::string("cannot create: ") + std::strerror(errno)};
  out << format_map(map);
  out.flush();
  if (!out) return Error{path, 0, "write error"};
  return Ok{};
}

Result<OccupancyMap> load_map(const std::string& path) { return load_text_file(path, parse_map); }

}  // namespace robuter::plan
