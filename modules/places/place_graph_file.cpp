// SPDX-License-Identifier: GPL-3.0-or-later
// Reads and checks a "robuter-places 1" file with the simulator's strict TOML reader.
#include "modules/places/place_graph_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "hal/sim/toml_fields.hpp"

namespace robuter::places {

namespace {

using sim::Error;
using sim::detail::Fields;
using sim::detail::ParseFailure;

constexpr std::string_view kFormat = "robuter-places 1";

class Reader {
 public:
  Reader(std::string_view text, std::string_view file) : file_(file), root_(sim::detail::parse_toml(text, file)) {}

  PlaceGraph read() {
    // First: a world or a configuration given for a place graph is told so, not its first table.
    if (!root_.contains("places")) fail(1, "missing [places] table (format = \"robuter-places 1\"): not a place graph");
    for (const auto& [k, v] : root_) {
      const std::string key(k.str());
      const bool array = key == "place" || key == "door";
      if (key != "places" && !array) fail(sim::detail::line_of(v), "unknown table '" + key + "' (expected [places], [[place]], [[door]])");
      if (array && !v.is_array_of_tables()) fail(sim::detail::line_of(v), "'" + key + "' must be written [[" + key + "]]");
      if (!array && !v.is_table()) fail(sim::detail::line_of(v), "'places' must be written [places]");
    }
    read_header();
    if (const auto* arr = root_.get_as<toml::array>("place"))
      for (const auto& n : *arr) read_place(*n.as_table());
    if (places_.empty()) fail(0, "no [[place]]: a place graph needs at least one place");
    check_overlaps();
    if (const auto* arr = root_.get_as<toml::array>("door"))
      for (const auto& n : *arr) read_door(*n.as_table());
    return PlaceGraph(std::move(places_), std::move(doors_));
  }

 private:
  [[noreturn]] void fail(int line, const std::string& message) const { throw ParseFailure{Error{file_, line, message}}; }

  void read_header() {
    const auto* t = root_.get_as<toml::table>("places");
    if (t == nullptr) fail(1, "missing [places] table (format = \"robuter-places 1\")");
    Fields f(*t, file_, "[places]");
    const auto format = f.opt_string("format");
    if (!format) f.fail(f.line(), "missing key 'format' (\"robuter-places 1\")");
    if (*format != kFormat) f.fail_at(*f.get("format"), "format: expected \"robuter-places 1\", found \"" + *format + "\"");
    scale_ = f.units();
    f.opt_string("world");
    f.finish();
  }

  // The `name` key of a [[`kind`]] row, unique among the `rows` read before it; the row's
  // messages name it from then on.
  template <class Row>
  std::string take_name(Fields& f, const char* kind, const std::vector<Row>& rows) {
    const auto name = f.opt_string("name");
    if (!name) f.fail(f.line(), "missing key 'name'");
    if (!valid_name(*name))
      f.fail_at(*f.get("name"), "name \"" + *name + "\": 1 to 15 letters, digits, '-' or '_'");
    if (std::any_of(rows.begin(), rows.end(), [&](const Row& r) { return r.name == *name; }))
      f.fail_at(*f.get("name"), "name \"" + *name + "\" is used twice");
    f.set_what(std::string("[[") + kind + "]] '" + *name + "'");
    return *name;
  }

  void read_place(const toml::table& t) {
    Fields f(t, file_, "[[place]] " + std::to_string(places_.size() + 1), scale_);
    Place p;
    p.name = take_name(f, "place", places_);
    p.area = f.points("area");
    p.centre = f.point("centre");
    f.finish();
    const int line = f.line();
    if (p.area.size() < 3) f.fail(line, "area: a polygon needs at least 3 vertices, found " + std::to_string(p.area.size()));
    const std::size_t n = p.area.size();
    for (std::size_t i = 0; i < n; ++i)
      if ((p.area[i] - p.area[(i + 1) % n]).norm() < 1e-6) f.fail(line, "area: vertex " + std::to_string(i + 1) + " repeats the next one");
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 2; j < n; ++j) {
        if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
        if (segments_cross(p.area[i], p.area[(i + 1) % n], p.area[j], p.area[(j + 1) % n]))
          f.fail(line, "area: edges " + std::to_string(i + 1) + " and " + std::to_string(j + 1) + " cross (the polygon is not simple)");
      }
    const double a = signed_area(p.area);
    if (std::abs(a) < 1e-4) f.fail(line, "area: the polygon has no area");
    if (a < 0.0) std::reverse(p.area.begin(), p.area.end());  // stored counter-clockwise
    if (!inside_polygon(p.area, p.centre))
      f.fail(line, "centre (" + coords(p.centre) + ") is outside the place's area");
    lines_.push_back(line);
    places_.push_back(std::move(p));
  }

  static std::string coords(const Vec2& v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3f, %.3f", v.x(), v.y());
    return buf;
  }

  static bool strictly_inside(const Place& in, const Vec2& v) {
    return inside_polygon(in.area, v) && distance_to_boundary(in.area, v) > 1e-3;
  }

  // Why: edges that run along the other place's edges cross nothing; points of a's edges (at a
  // quarter, half, three quarters) moved 5 mm into a find b's floor when a overlaps it there.
  static bool inner_edge_points_inside(const Place& a, const Place& b) {
    const std::size_t n = a.area.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 p = a.area[i], q = a.area[(i + 1) % n];
      const Vec2 d = (q - p).normalized();
      const Vec2 inward(-d.y(), d.x());  // left of the edge: inside a counter-clockwise polygon
      for (const double t : {0.25, 0.5, 0.75})
        if (strictly_inside(b, p + t * (q - p) + 0.005 * inward)) return true;
    }
    return false;
  }

  // Two places overlap when their edges cross, a vertex or the centre of one lies inside the
  // other off its boundary, or points just inside one's edges lie inside the other (shared edges
  // and vertices are allowed; an overlap thinner than 5 mm goes unseen).
  void check_overlaps() const {
    for (std::size_t i = 0; i < places_.size(); ++i)
      for (std::size_t j = i + 1; j < places_.size(); ++j) {
        const Place& a = places_[i];
        const Place& b = places_[j];
        bool overlap = strictly_inside(a, b.centre) || strictly_inside(b, a.centre);
        for (const Vec2& v : a.area) overlap = overlap || strictly_inside(b, v);
        for (const Vec2& v : b.area) overlap = overlap || strictly_inside(a, v);
        overlap = overlap || inner_edge_points_inside(a, b) || inner_edge_points_inside(b, a);
        for (std::size_t p = 0; p < a.area.size() && !overlap; ++p)
          for (std::size_t q = 0; q < b.area.size() && !overlap; ++q)
            overlap = segments_cross(a.area[p], a.area[(p + 1) % a.area.size()], b.area[q],
                                     b.area[(q + 1) % b.area.size()]);
        if (overlap)
          fail(lines_[j], "[[place]] '" + b.name + "': its area overlaps place '" + a.name + "' (places may share edges, not floor)");
      }
  }

  void read_door(const toml::table& t) {
    Fields f(t, file_, "[[door]] " + std::to_string(doors_.size() + 1), scale_);
    Door d;
    d.name = take_name(f, "door", doors_);
    const toml::node* between = f.get("between");
    if (between == nullptr) f.fail(f.line(), "missing key 'between' ([\"place\", \"place\"])");
    const auto* arr = between->as_array();
    if (arr == nullptr || arr->size() != 2 || !arr->get(0)->is_string() || !arr->get(1)->is_string())
      f.fail_at(*between, "between: expected two place names [\"a\", \"b\"]");
    std::size_t ends[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
      const std::string name = arr->get(static_cast<std::size_t>(k))->value_or(std::string{});
      std::size_t i = 0;
      while (i < places_.size() && places_[i].name != name) ++i;
      if (i == places_.size()) f.fail_at(*between, "between: no place named \"" + name + "\"");
      ends[k] = i;
    }
    if (ends[0] == ends[1]) f.fail_at(*between, "between: a door joins two different places");
    d.a = ends[0];
    d.b = ends[1];
    d.at = f.point("at");
    d.width = f.length("width");
    f.finish();
    if (!(d.width > 0.0 && d.width <= 10.0)) f.fail_at(*f.get("width"), "width: expected 0 < width <= 10 m");
    for (const std::size_t i : ends) {
      const double off = distance_to_boundary(places_[i].area, d.at);
      if (off > kDoorOnBoundary) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "at (%s) is %.2f m from place '", coords(d.at).c_str(), off);
        f.fail_at(*f.get("at"), buf + places_[i].name + "' (a door lies on both its places' boundaries, within 0.15 m)");
      }
    }
    doors_.push_back(std::move(d));
  }

  std::string file_;            // for messages
  toml::table root_;            // the parsed file
  double scale_ = 1.0;          // the file's length unit, m
  std::vector<Place> places_;   // read so far
  std::vector<int> lines_;      // per place: its [[place]] line
  std::vector<Door> doors_;     // read so far
};

}  // namespace

sim::Result<PlaceGraph> parse_place_graph(std::string_view text, std::string_view file) {
  try {
    Reader r(text, file);
    return r.read();
  } catch (const ParseFailure& e) {
    return e.error;
  }
}

sim::Result<PlaceGraph> load_place_graph(const std::string& path) {
  std::string text;
  if (auto why = sim::detail::read_text_file(path, text)) return Error{path, 0, *why};
  return parse_place_graph(text, path);
}

}  // namespace robuter::places
