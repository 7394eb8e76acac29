// SPDX-License-Identifier: GPL-3.0-or-later
// The project's TOML world loader: walls with doors, boxes, rectangles, closed polygons, start,
// goal and markers, in metres, centimetres or millimetres; every error with file and line.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "hal/sim/toml_fields.hpp"
#include "hal/sim/world_io.hpp"

namespace robuter::sim {

namespace {

using detail::Fields;
using detail::line_of;
using detail::ParseFailure;

// Top-level entries and whether each is a single table or an array of tables.
struct Section {
  const char* key;  // TOML key
  bool array;       // written [[key]] (true) or [key] (false)
};
constexpr Section kSections[] = {{"world", false},    {"start", false},  {"goal", false},
                                 {"wall", true},      {"box", true},     {"rectangle", true},
                                 {"polygon", true},   {"marker", true}};

// Reads one world file; throws ParseFailure on the first error.
class TomlWorldReader {
 public:
  TomlWorldReader(std::string_view text, std::string_view file)
      : file_(file), root_(detail::parse_toml(text, file)) {}

  // Sections in a fixed order (units before lengths); the grid is built at the end.
  World read() {
    check_sections();
    world_.source = file_;
    read_world();
    read_start_goal();
    for_each("wall", [&](const toml::table& t, int i) { read_wall(t, i); });
    for_each("box", [&](const toml::table& t, int i) { read_box(t, i); });
    for_each("rectangle", [&](const toml::table& t, int i) { read_rectangle(t, i); });
    for_each("polygon", [&](const toml::table& t, int i) { read_polygon(t, i); });
    for_each("marker", [&](const toml::table& t, int i) { read_marker(t, i); });
    if (!world_.start) fail(1, "missing [start] table (the robot's start pose)");
    world_.finalize();
    return std::move(world_);
  }

 private:
  [[noreturn]] void fail(int line, const std::string& message) const {
    throw ParseFailure{Error{file_, line, message}};
  }

  // Unknown top-level keys and [x] written for [[x]] (or the reverse) are errors.
  void check_sections() {
    for (const auto& [k, v] : root_) {
      const Section* sec = nullptr;
      for (const auto& s : kSections) {
        if (k.str() == s.key) sec = &s;
      }
      const int line = static_cast<int>(k.source().begin.line);
      if (sec == nullptr) fail(line, "unknown key '" + std::string(k.str()) + "'");
      if (sec->array && !v.is_array_of_tables()) {
        fail(line, "'" + std::string(k.str()) + "' must be written [[" + sec->key + "]]");
      }
      if (!sec->array && !v.is_table()) {
        fail(line, "'" + std::string(k.str()) + "' must be a table [" + sec->key + "]");
      }
    }
  }

  // Calls f(table, 1-based index) for each [[key]] entry.
  template <class F>
  void for_each(const char* key, F&& f) {
    const auto* arr = root_.get_as<toml::array>(key);
    if (arr == nullptr) return;
    int i = 0;
    for (const auto& n : *arr) f(*n.as_table(), ++i);
  }

  // A name for an object: the file's, else "<kind> <index>"; duplicates are refused.
  std::string take_name(Fields& f, const char* kind, int index) {
    const auto given = f.opt_string("name");
    std::string name = given ? *given : std::string(kind) + " " + std::to_string(index);
    f.set_what(std::string("[[") + kind + "]] '" + name + "'");
    if (given) {
      if (name.empty()) f.fail(f.line(), "name: must not be empty");
      const auto [it, fresh] = names_.emplace(name, f.line());
      if (!fresh) {
        f.fail(f.line(), "duplicate name '" + name + "' (first used on line " +
                             std::to_string(it->second) + ")");
      }
    }
    return name;
  }

  // An object's optional `surface` key ("standard", "smooth" or "rough"); `fallback` when absent.
  Surface read_surface(Fields& f, Surface fallback) {
    const auto given = f.opt_string("surface");
    if (!given) return fallback;
    if (*given == "standard") return Surface::standard;
    if (*given == "smooth") return Surface::smooth;
    if (*given == "rough") return Surface::rough;
    f.fail_at(*f.get("surface"), "surface: must be \"standard\", \"smooth\" or \"rough\", found \"" + *given + "\"");
  }

  // [world]: name, units (m, cm, mm), wall_thickness, surface (the objects' default).
  void read_world() {
    const auto* t = root_.get_as<toml::table>("world");
    world_.name = stem();
    if (t == nullptr) return;
    Fields f(*t, file_, "[world]");
    if (const auto n = f.opt_string("name")) world_.name = *n;
    scale_ = f.units();
    Fields g(*t, file_, "[world]", scale_);
    g.get("name");
    g.get("units");
    if (const auto th = g.opt_length("wall_thickness")) {
      if (*th <= 0.0) g.fail_at(*g.get("wall_thickness"), "wall_thickness: must be positive");
      wall_thickness_ = *th;
    }
    surface_ = read_surface(g, Surface::standard);
    g.finish();
  }

  // [start] x, y, heading_deg (required table); [goal] x, y (optional).
  void read_start_goal() {
    if (const auto* t = root_.get_as<toml::table>("start")) {
      Fields f(*t, file_, "[start]", scale_);
      Pose p{f.length("x"), f.length("y"), deg_to_rad(f.opt_number("heading_deg").value_or(0.0))};
      f.finish();
      world_.start = p;
      world_.start_line = f.line();
    }
    if (const auto* t = root_.get_as<toml::table>("goal")) {
      Fields f(*t, file_, "[goal]", scale_);
      world_.goal = Vec2(f.length("x"), f.length("y"));
      f.finish();
      world_.goal_line = f.line();
    }
  }

  // A straight wall piece from s0 to s1 along the wall line, as a rectangle polygon.
  void add_piece(const std::string& name, int line, const Vec2& from, const Vec2& u, double s0,
                 double s1, double thickness, Surface surface) {
    if (s1 - s0 <= 1e-12) return;
    const Vec2 n(-u.y(), u.x());
    const Vec2 a = from + s0 * u, b = from + s1 * u;
    const double h = 0.5 * thickness;
    world_.add_obstacle({name, {a - h * n, b - h * n, b + h * n, a + h * n}, line, surface});
  }

  // [[wall]]: a straight wall (from/to) with optional doors, or a chain of walls (points, with
  // optional closed = true). Wall ends are squared off half a thickness beyond their end points
  // so walls meeting at a point make a solid corner; door jambs are not extended.
  void read_wall(const toml::table& t, int index) {
    Fields f(t, file_, "[[wall]]", scale_);
    const std::string name = take_name(f, "wall", index);
    const double th = f.opt_length("thickness").value_or(wall_thickness_);
    if (th <= 0.0) f.fail_at(*f.get("thickness"), "thickness: must be positive");
    const Surface surface = read_surface(f, surface_);
    const auto* doors_node = f.get("doors");
    const auto* points_node = f.get("points");
    const auto closed = f.opt_bool("closed");
    if (points_node != nullptr) {
      if (f.get("from") != nullptr || f.get("to") != nullptr) {
        f.fail(f.line(), "give either from/to or points, not both");
      }
      if (doors_node != nullptr) {
        f.fail_at(*doors_node, "doors: only a straight wall (from/to) can have doors");
      }
      auto pts = f.points("points");
      if (pts.size() < 2) f.fail_at(*points_node, "bad count: points needs at least 2 points");
      if (closed.value_or(false)) pts.push_back(pts.front());
      f.finish();
      for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        const Vec2 d = pts[i + 1] - pts[i];
        const double len = d.norm();
        if (len <= 0.0) f.fail_at(*points_node, "points: two consecutive points are equal");
        add_piece(name, f.line(), pts[i], d / len, -0.5 * th, len + 0.5 * th, th, surface);
      }
      return;
    }
    if (closed) f.fail_at(*f.get("closed"), "closed: only meaningful with points");
    const Vec2 from = f.point("from"), to = f.point("to");
    const double len = (to - from).norm();
    if (len <= 0.0) f.fail(f.line(), "from and to are the same point");
    const Vec2 u = (to - from) / len;
    // A door's opening along the wall line.
    struct Gap {
      double s0, s1;     // start and end along the wall from `from`, m
      int line;          // line of the door entry
      std::string name;  // door name, for messages
    };
    std::vector<Gap> gaps;
    if (doors_node != nullptr) {
      const auto* arr = doors_node->as_array();
      if (arr == nullptr) {
        f.fail_at(*doors_node, "doors: expected an array of { at, width } tables, found " +
                                   detail::type_name(*doors_node));
      }
      int k = 0;
      for (const auto& dn : *arr) {
        ++k;
        const auto* dt = dn.as_table();
        if (dt == nullptr) f.fail_at(dn, "doors: expected { at, width }, found " + detail::type_name(dn));
        Fields d(*dt, file_, f.what() + " door " + std::to_string(k), scale_);
        const std::string dname = d.opt_string("name").value_or(name + " door " + std::to_string(k));
        d.set_what(f.what() + " door '" + dname + "'");
        const double at = d.length("at"), width = d.length("width");
        d.finish();
        const int line = line_of(dn);
        if (width <= 0.0) d.fail(line, "width: must be positive");
        if (at - 0.5 * width < 0.0 || at + 0.5 * width > len) {
          d.fail(line, "does not fit in its wall (wall length " + std::to_string(len) + " m)");
        }
        gaps.push_back({at - 0.5 * width, at + 0.5 * width, line, dname});
        world_.doors.push_back({dname, from + at * u, width, std::atan2(u.y(), u.x()), th});
      }
    }
    f.finish();
    std::sort(gaps.begin(), gaps.end(), [](const Gap& a, const Gap& b) { return a.s0 < b.s0; });
    for (std::size_t i = 1; i < gaps.size(); ++i) {
      if (gaps[i].s0 < gaps[i - 1].s1) {
        fail(gaps[i].line, f.what() + ": doors '" + gaps[i - 1].name + "' and '" + gaps[i].name +
                               "' overlap");
      }
    }
    double s = -0.5 * th;
    for (const auto& g : gaps) {
      add_piece(name, f.line(), from, u, s, g.s0, th, surface);
      s = g.s1;
    }
    add_piece(name, f.line(), from, u, s, len + 0.5 * th, th, surface);
  }

  // [[box]]: centre, size [along its x, along its y], angle_deg.
  void read_box(const toml::table& t, int index) {
    Fields f(t, file_, "[[box]]", scale_);
    const std::string name = take_name(f, "box", index);
    const Vec2 c = f.point("center");
    const Vec2 size = f.point("size");
    const double a = deg_to_rad(f.opt_number("angle_deg").value_or(0.0));
    const Surface surface = read_surface(f, surface_);
    f.finish();
    if (size.x() <= 0.0 || size.y() <= 0.0) f.fail_at(*f.get("size"), "size: must be positive");
    const Vec2 u(std::cos(a), std::sin(a)), v(-std::sin(a), std::cos(a));
    const Vec2 hx = 0.5 * size.x() * u, hy = 0.5 * size.y() * v;
    world_.add_obstacle({name, {c - hx - hy, c + hx - hy, c + hx + hy, c - hx + hy}, f.line(), surface});
  }

  // [[rectangle]]: axis-aligned, min and max corners.
  void read_rectangle(const toml::table& t, int index) {
    Fields f(t, file_, "[[rectangle]]", scale_);
    const std::string name = take_name(f, "rectangle", index);
    const Vec2 lo = f.point("min"), hi = f.point("max");
    const Surface surface = read_surface(f, surface_);
    f.finish();
    if (hi.x() <= lo.x() || hi.y() <= lo.y()) {
      f.fail(f.line(), "max must be above and to the right of min");
    }
    world_.add_obstacle({name, {lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}}, f.line(), surface});
  }

  // [[polygon]]: points, closed explicitly by repeating the first point at the end.
  void read_polygon(const toml::table& t, int index) {
    Fields f(t, file_, "[[polygon]]", scale_);
    const std::string name = take_name(f, "polygon", index);
    auto pts = f.points("points");
    const auto* node = f.get("points");
    const Surface surface = read_surface(f, surface_);
    f.finish();
    if (pts.size() < 4) {
      f.fail_at(*node, "bad count: a polygon needs at least 3 corners plus the closing point (" +
                           std::to_string(pts.size()) + " given)");
    }
    if (pts.front() != pts.back()) {
      f.fail_at(*node, "polygon is not closed: repeat the first point at the end");
    }
    pts.pop_back();
    if (std::abs(polygon_area(pts)) <= 1e-12) f.fail_at(*node, "polygon has no area");
    world_.add_obstacle({name, std::move(pts), f.line(), surface});
  }

  // [[marker]]: a named pose (x, y, heading_deg).
  void read_marker(const toml::table& t, int index) {
    Fields f(t, file_, "[[marker]]", scale_);
    const std::string name = take_name(f, "marker", index);
    Pose p{f.length("x"), f.length("y"), deg_to_rad(f.opt_number("heading_deg").value_or(0.0))};
    f.finish();
    world_.markers.push_back({name, p});
  }

  // The file name without directories and extension, the default world name.
  std::string stem() const {
    std::string s = file_;
    if (const auto slash = s.find_last_of('/'); slash != std::string::npos) s = s.substr(slash + 1);
    if (const auto dot = s.find_last_of('.'); dot != std::string::npos) s.resize(dot);
    return s;
  }

  std::string file_;                      // file name for messages
  toml::table root_;                      // parsed document
  World world_;                           // being built
  double scale_ = 1.0;                    // file length unit, m
  double wall_thickness_ = 0.10;          // default wall thickness, m
  Surface surface_ = Surface::standard;   // default surface of the objects ([world] surface)
  std::map<std::string, int> names_;      // object names seen, with their lines
};

}  // namespace

// Reading, then the pose checks; the internal exception becomes an Error value here.
Result<World> parse_world_toml(std::string_view text, std::string_view file,
                               const RobotGeometry& robot) {
  try {
    World w = TomlWorldReader(text, file).read();
    if (Status s = check_world_poses(w, robot); !s) return s.error();
    return w;
  } catch (const ParseFailure& e) {
    return e.error;
  }
}

// Finds which obstacle the body meets, for a useful message (linear scan: load time only).
Status check_world_poses(const World& world, const RobotGeometry& robot) {
  auto obstacle_label = [&](int i) {
    const auto& ob = world.obstacles()[i];
    std::string s = "'" + ob.name + "'";
    if (ob.line > 0) s += " (line " + std::to_string(ob.line) + ")";
    return s;
  };
  if (world.start) {
    const Pose& p = *world.start;
    const Box body = robot.body();
    for (const auto& sg : world.segments()) {
      if (segment_meets_box(to_local(p, sg.a), to_local(p, sg.b), body)) {
        return Error{world.source, world.start_line,
                     "start pose is inside a wall: the robot's body there overlaps obstacle " +
                         obstacle_label(sg.obstacle)};
      }
    }
    if (const int i = world.obstacle_containing({p.x, p.y}); i >= 0) {
      return Error{world.source, world.start_line,
                   "start pose is inside obstacle " + obstacle_label(i)};
    }
  }
  if (world.goal) {
    if (const int i = world.obstacle_containing(*world.goal); i >= 0) {
      return Error{world.source, world.goal_line, "goal is inside obstacle " + obstacle_label(i)};
    }
  }
  return Ok{};
}

// The extension picks the format: the seed's files have none of their own.
Result<World> load_world(const std::filesystem::path& path, const RobotGeometry& robot) {
  std::string text;
  if (auto why = detail::read_text_file(path.string(), text)) return Error{path.string(), 0, *why};
  if (path.extension() == ".toml") return parse_world_toml(text, path.string(), robot);
  auto w = parse_world_env(text, path.string());
  return w;
}

bool is_world_file(const std::filesystem::path& path) {
  const auto ext = path.extension();
  if (ext == ".env") return true;
  return ext == ".toml" && path.stem().extension() != ".places";
}

}  // namespace robuter::sim
