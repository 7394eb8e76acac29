// SPDX-License-Identifier: GPL-3.0-or-later
// Parsers for the thesis' parameter and environment files, and polygon edge rasterisation.
#include "modules/planner/lib/thesis_files.hpp"

#include "modules/planner/lib/bresenham.hpp"
#include "modules/planner/lib/text_reader.hpp"

namespace robuter::plan {

Result<ThesisParameters> parse_parameters(std::string_view text, const std::string& name) {
  TokenReader in(text, name);
  ThesisParameters p;
  double* fields[7] = {&p.radius, &p.speed, &p.heading_deg, &p.start.x, &p.start.y, &p.goal.x, &p.goal.y};
  const char* what[7] = {"robot radius (m)", "robot speed (m/s)", "initial heading (degrees)",
                         "start x (m)", "start y (m)", "goal x (m)", "goal y (m)"};
  for (int i = 0; i < 7; ++i) {
    auto v = in.real(what[i]);
    if (!v) return v.error();
    *fields[i] = *v;
    if (i == 0 && *v < 0.0) return in.error(in.line(), "robot radius must not be negative");
    if (i == 1 && *v < 0.0) return in.error(in.line(), "robot speed must not be negative");
  }
  if (auto end = in.expect_end(); !end) return end.error();
  return p;
}

Result<ThesisParameters> load_parameters(const std::string& path) {
  return load_text_file(path, parse_parameters);
}

Result<std::vector<Polygon>> parse_environment(std::string_view text, const std::string& name) {
  TokenReader in(text, name);
  std::vector<Polygon> out;
  const auto count = in.integer("number of obstacles");
  if (!count) return count.error();
  if (*count < 0 || *count > 1'000'000) return in.error(in.line(), "bad number of obstacles " + std::to_string(*count));
  for (long long o = 0; o < *count; ++o) {
    const std::string which = "obstacle " + std::to_string(o + 1) + " of " + std::to_string(*count);
    const auto n = in.integer("vertex count of " + which);
    if (!n) return n.error();
    if (*n < 1 || *n > 1'000'000)
      return in.error(in.line(), "bad vertex count " + std::to_string(*n) + " for " + which);
    Polygon poly;
    poly.vertices.reserve(static_cast<std::size_t>(*n));
    for (long long v = 0; v < *n; ++v) {
      const std::string vertex = "vertex " + std::to_string(v + 1) + " of " + which;
      const auto x = in.real("x of " + vertex);
      if (!x) return x.error();
      const auto y = in.real("y of " + vertex);
      if (!y) return y.error();
      poly.vertices.push_back({*x, *y});
    }
    out.push_back(std::move(poly));
  }
  if (auto end = in.expect_end(); !end) return end.error();
  return out;
}

Result<std::vector<Polygon>> load_environment(const std::string& path) {
  return load_text_file(path, parse_environment);
}

void rasterise_polygons(OccupancyMap& map, const std::vector<Polygon>& polygons) {
  for (const Polygon& poly : polygons) {
    const std::size_t n = poly.vertices.size();
    if (n == 0) continue;
    for (std::size_t i = 0; i < n; ++i) {
      Point2 p = poly.vertices[i];
      Point2 q = poly.vertices[(i + 1) % n];
      if (!clip_segment_to_map(map.geometry(), p, q)) continue;
      const Cell a = map.cell_of(p);
      const Cell b = map.cell_of(q);
      for_each_line_cell(a, b, [&](int x, int y) {
        map.mark_occupied({x, y});
        return true;
      });
    }
  }
}

}  // namespace robuter::plan
