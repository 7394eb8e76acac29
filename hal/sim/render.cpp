// Cairo renderer: one drawing routine, written to a PNG image surface or an SVG surface.
#include "hal/sim/render.hpp"

#include <cairo-svg.h>
#include <fontconfig/fontconfig.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace robuter::sim {

namespace {

// Colours (r, g, b) of the picture's elements.
struct Rgb {
  double r, g, b;  // 0..1
};
constexpr Rgb kFloor{1.0, 1.0, 1.0};
constexpr Rgb kGrid{0.90, 0.90, 0.92};
constexpr Rgb kObstacle{0.55, 0.55, 0.58};
constexpr Rgb kObstacleEdge{0.20, 0.20, 0.22};
constexpr Rgb kDoor{0.10, 0.60, 0.20};
constexpr Rgb kRobot{0.55, 0.70, 0.95};
constexpr Rgb kRobotEdge{0.05, 0.15, 0.45};
constexpr Rgb kTrail{0.75, 0.05, 0.35};
constexpr Rgb kBeam{0.95, 0.75, 0.10};
constexpr Rgb kPanTilt{0.70, 0.10, 0.70};
constexpr Rgb kGoal{0.85, 0.10, 0.10};
constexpr Rgb kText{0.10, 0.10, 0.10};

// Selects a colour (with transparency) for the next fill or stroke.
void set(cairo_t* cr, const Rgb& c, double alpha = 1.0) {
  cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
}

// Starts a new path piece at a world point.
void move(cairo_t* cr, const View& v, const Vec2& w) {
  const Vec2 d = v.to_device(w);
  cairo_move_to(cr, d.x(), d.y());
}

// Extends the current path to a world point.
void line(cairo_t* cr, const View& v, const Vec2& w) {
  const Vec2 d = v.to_device(w);
  cairo_line_to(cr, d.x(), d.y());
}

// Small text at a world point, offset in device units.
void label(cairo_t* cr, const View& v, const Vec2& w, const std::string& text, double dx = 4,
           double dy = -4, double size = 11) {
  const Vec2 d = v.to_device(w);
  cairo_set_font_size(cr, size);
  set(cr, kText);
  cairo_move_to(cr, d.x() + dx, d.y() + dy);
  cairo_show_text(cr, text.c_str());
}

// A filled wedge (cone) from `o` along `dir`, half-angle `half`, radius `r`.
void wedge(cairo_t* cr, const View& v, const Vec2& o, double dir, double half, double r) {
  const Vec2 d = v.to_device(o);
  const double rr = r * v.scale;
  cairo_move_to(cr, d.x(), d.y());
  // Device y points down, so world angle a becomes -a.
  cairo_arc(cr, d.x(), d.y(), rr, -(dir + half), -(dir - half));
  cairo_close_path(cr);
}

// A light 1 m grid, to read distances off the picture.
void draw_grid(cairo_t* cr, const View& v) {
  set(cr, kGrid);
  cairo_set_line_width(cr, 1.0);
  for (double x = std::ceil(v.world.lo.x()); x <= v.world.hi.x(); x += 1.0) {
    move(cr, v, {x, v.world.lo.y()});
    line(cr, v, {x, v.world.hi.y()});
  }
  for (double y = std::ceil(v.world.lo.y()); y <= v.world.hi.y(); y += 1.0) {
    move(cr, v, {v.world.lo.x(), y});
    line(cr, v, {v.world.hi.x(), y});
  }
  cairo_stroke(cr);
}

// Obstacles filled grey with a dark outline; thin (two-vertex) walls as thick lines.
void draw_obstacles(cairo_t* cr, const View& v, const World& w) {
  for (const auto& ob : w.obstacles()) {
    const auto& p = ob.vertices;
    if (p.size() < 2) continue;
    move(cr, v, p[0]);
    for (std::size_t i = 1; i < p.size(); ++i) line(cr, v, p[i]);
    if (p.size() >= 3) {
      cairo_close_path(cr);
      set(cr, kObstacle);
      cairo_fill_preserve(cr);
    }
    set(cr, kObstacleEdge);
    cairo_set_line_width(cr, p.size() >= 3 ? 1.0 : 2.5);
    cairo_stroke(cr);
  }
}

// Doors: a green line across the opening, with its name and width.
void draw_doors(cairo_t* cr, const View& v, const World& w, bool labels) {
  for (const auto& d : w.doors) {
    const Vec2 u(std::cos(d.wall_direction), std::sin(d.wall_direction));
    set(cr, kDoor);
    cairo_set_line_width(cr, 2.0);
    const double dash[] = {4.0, 3.0};
    cairo_set_dash(cr, dash, 2, 0.0);
    move(cr, v, d.centre - 0.5 * d.width * u);
    line(cr, v, d.centre + 0.5 * d.width * u);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0.0);
    if (labels) {
      label(cr, v, d.centre, d.name + " " + std::to_string(static_cast<int>(std::lround(d.width * 100))) + " cm");
    }
  }
}

// An outline of the body at a pose (start pose, markers) or a filled body (the robot).
void body_path(cairo_t* cr, const View& v, const RobotGeometry& g, const Pose& p) {
  Vec2 c[4];
  footprint_corners(g, p, c);
  move(cr, v, c[0]);
  for (int i = 1; i < 4; ++i) line(cr, v, c[i]);
  cairo_close_path(cr);
}

// A small arrow for a pose.
void pose_arrow(cairo_t* cr, const View& v, const Pose& p, double len, const Rgb& colour) {
  const Vec2 o(p.x, p.y);
  const Vec2 u = heading_vector(p);
  const Vec2 n(-u.y(), u.x());
  set(cr, colour);
  cairo_set_line_width(cr, 1.5);
  move(cr, v, o);
  line(cr, v, o + len * u);
  cairo_stroke(cr);
  move(cr, v, o + len * u);
  line(cr, v, o + 0.7 * len * u + 0.15 * len * n);
  line(cr, v, o + 0.7 * len * u - 0.15 * len * n);
  cairo_close_path(cr);
  cairo_fill(cr);
}

// Start pose (dashed body outline), goal (red cross) and named markers (arrows).
void draw_marks(cairo_t* cr, const View& v, const Scene& s, bool labels) {
  const World& w = *s.world;
  if (w.start) {
    body_path(cr, v, s.geometry, *w.start);
    set(cr, kRobotEdge, 0.6);
    cairo_set_line_width(cr, 1.0);
    const double dash[] = {3.0, 3.0};
    cairo_set_dash(cr, dash, 2, 0.0);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0.0);
    if (labels) label(cr, v, {w.start->x, w.start->y}, "start", 4, 14);
  }
  if (w.goal) {
    const Vec2 d = v.to_device(*w.goal);
    set(cr, kGoal);
    cairo_set_line_width(cr, 2.5);
    cairo_move_to(cr, d.x() - 7, d.y() - 7);
    cairo_line_to(cr, d.x() + 7, d.y() + 7);
    cairo_move_to(cr, d.x() - 7, d.y() + 7);
    cairo_line_to(cr, d.x() + 7, d.y() - 7);
    cairo_stroke(cr);
    if (labels) label(cr, v, *w.goal, "goal", 8, -8);
  }
  for (const auto& m : w.markers) {
    pose_arrow(cr, v, m.pose, 0.3, kGoal);
    if (labels) label(cr, v, {m.pose.x, m.pose.y}, m.name, 4, 12, 10);
  }
}

// Where the robot has been, as one polyline.
void draw_trail(cairo_t* cr, const View& v, const Trail& t) {
  if (t.size() < 2) return;
  set(cr, kTrail);
  cairo_set_line_width(cr, 2.0);
  move(cr, v, t[0]);
  for (std::size_t i = 1; i < t.size(); ++i) line(cr, v, t[i]);
  cairo_stroke(cr);
}

// Echoing beams: a translucent cone to the echo and a bold arc at the range; silent beams: a
// thin dotted axis to the time-out range.
void draw_beams(cairo_t* cr, const View& v, const std::vector<SonarBeam>& beams, const Rgb& c,
                bool cones, bool labels) {
  for (const auto& b : beams) {
    const Vec2 u(std::cos(b.direction), std::sin(b.direction));
    if (b.range > 0.0) {
      if (cones && b.half_angle > 0.0) {
        wedge(cr, v, b.origin, b.direction, b.half_angle, b.range);
        set(cr, c, 0.18);
        cairo_fill(cr);
        const Vec2 d = v.to_device(b.origin);
        cairo_new_sub_path(cr);
        cairo_arc(cr, d.x(), d.y(), b.range * v.scale, -(b.direction + b.half_angle),
                  -(b.direction - b.half_angle));
        set(cr, c, 0.95);
        cairo_set_line_width(cr, 2.0);
        cairo_stroke(cr);
      }
      set(cr, c, 0.8);
      cairo_set_line_width(cr, 1.0);
      move(cr, v, b.origin);
      line(cr, v, b.origin + b.range * u);
      cairo_stroke(cr);
    } else {
      set(cr, c, 0.45);
      cairo_set_line_width(cr, 0.8);
      const double dash[] = {2.0, 4.0};
      cairo_set_dash(cr, dash, 2, 0.0);
      move(cr, v, b.origin);
      line(cr, v, b.origin + b.max_range * u);
      cairo_stroke(cr);
      cairo_set_dash(cr, nullptr, 0, 0.0);
    }
    if (labels && b.number > 0) {
      label(cr, v, b.origin + 0.12 * u, std::to_string(b.number), -3, 3, 8);
    }
  }
}

// The robot: filled body, wheels at the axle, heading arrow.
void draw_robot(cairo_t* cr, const View& v, const RobotGeometry& g, const Pose& p) {
  body_path(cr, v, g, p);
  set(cr, kRobot, 0.85);
  cairo_fill_preserve(cr);
  set(cr, kRobotEdge);
  cairo_set_line_width(cr, 1.5);
  cairo_stroke(cr);
  for (const double side : {-1.0, 1.0}) {
    const double y = side * 0.5 * g.wheel_base;
    move(cr, v, to_world(p, {-0.1, y - 0.025}));
    line(cr, v, to_world(p, {0.1, y - 0.025}));
    line(cr, v, to_world(p, {0.1, y + 0.025}));
    line(cr, v, to_world(p, {-0.1, y + 0.025}));
    cairo_close_path(cr);
    set(cr, kRobotEdge);
    cairo_fill(cr);
  }
  pose_arrow(cr, v, p, 0.8 * g.axle_to_front, kRobotEdge);
}

// Enlarges a box to contain a point.
void grow(Box& b, const Vec2& p) {
  b.lo = b.lo.cwiseMin(p);
  b.hi = b.hi.cwiseMax(p);
}

// Shared by both file formats: makes the surface, draws, reports cairo's status.
Status finish_surface(cairo_surface_t* surface, const Scene& scene, const View& view,
                      const RenderOptions& options, const std::filesystem::path& path, bool png) {
  cairo_t* cr = cairo_create(surface);
  render(cr, scene, view, options);
  cairo_destroy(cr);
  cairo_status_t st = CAIRO_STATUS_SUCCESS;
  if (png) {
    st = cairo_surface_write_to_png(surface, path.string().c_str());
  } else {
    cairo_surface_finish(surface);
    st = cairo_surface_status(surface);
  }
  cairo_surface_destroy(surface);
  if (st != CAIRO_STATUS_SUCCESS) {
    return Error{path.string(), 0, std::string("cannot write the picture: ") + cairo_status_to_string(st)};
  }
  return Ok{};
}

}  // namespace

// World units with y up: scale by the resolution, flip y, move the world's corner to 0.
void View::apply(cairo_t* cr) const {
  cairo_scale(cr, scale, -scale);
  cairo_translate(cr, -world.lo.x(), -world.hi.y());
}

// Everything that will be drawn contributes to the bounds.
View make_view(const Scene& scene, const RenderOptions& options) {
  Box b{Vec2::Constant(std::numeric_limits<double>::infinity()),
        Vec2::Constant(-std::numeric_limits<double>::infinity())};
  if (scene.world != nullptr) {
    const World& w = *scene.world;
    if (!w.segments().empty()) {
      grow(b, w.bounds().lo);
      grow(b, w.bounds().hi);
    }
    if (w.start) grow(b, {w.start->x, w.start->y});
    if (w.goal) grow(b, *w.goal);
    for (const auto& m : w.markers) grow(b, {m.pose.x, m.pose.y});
  }
  if (scene.robot) {
    Vec2 c[4];
    footprint_corners(scene.geometry, *scene.robot, c);
    for (const auto& p : c) grow(b, p);
  }
  if (scene.trail != nullptr) {
    for (std::size_t i = 0; i < scene.trail->size(); ++i) grow(b, (*scene.trail)[i]);
  }
  if (!(b.lo.x() <= b.hi.x())) b = {Vec2(-1, -1), Vec2(1, 1)};
  b.lo -= Vec2::Constant(options.margin);
  b.hi += Vec2::Constant(options.margin);
  View v;
  v.world = b;
  v.scale = options.pixels_per_metre > 0.0 ? options.pixels_per_metre : 60.0;
  v.width = std::max(1, static_cast<int>(std::ceil((b.hi.x() - b.lo.x()) * v.scale - 1e-6)));
  v.height = std::max(1, static_cast<int>(std::ceil((b.hi.y() - b.lo.y()) * v.scale - 1e-6)));
  return v;
}

// Layers, bottom to top: floor, grid, underlay, obstacles, doors, marks, beams, trail, robot,
// pan-tilt, overlay, title.
void render(cairo_t* cr, const Scene& scene, const View& view, const RenderOptions& options) {
  cairo_save(cr);
  set(cr, kFloor);
  cairo_paint(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  if (options.grid) draw_grid(cr, view);
  if (scene.underlay) {
    cairo_save(cr);
    scene.underlay(cr, view);
    cairo_restore(cr);
  }
  if (scene.world != nullptr) {
    draw_obstacles(cr, view, *scene.world);
    draw_doors(cr, view, *scene.world, options.labels);
    draw_marks(cr, view, scene, options.labels);
  }
  draw_beams(cr, view, scene.beams, kBeam, options.cones, options.labels);
  if (scene.trail != nullptr) draw_trail(cr, view, *scene.trail);
  if (scene.robot) draw_robot(cr, view, scene.geometry, *scene.robot);
  draw_beams(cr, view, scene.pan_tilt, kPanTilt, options.cones, false);
  if (scene.overlay) {
    cairo_save(cr);
    scene.overlay(cr, view);
    cairo_restore(cr);
  }
  if (!scene.title.empty()) {
    cairo_set_font_size(cr, 14);
    set(cr, kText);
    cairo_move_to(cr, 8, 18);
    cairo_show_text(cr, scene.title.c_str());
  }
  cairo_restore(cr);
}

// An ARGB image surface sized by make_view, written with cairo's PNG writer.
Status render_png(const Scene& scene, const RenderOptions& options,
                  const std::filesystem::path& path) {
  const View v = make_view(scene, options);
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, v.width, v.height);
  if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(s);
    return Error{path.string(), 0, "cannot create a picture of that size"};
  }
  return finish_surface(s, scene, v, options, path, true);
}

// A vector picture of the same drawing, units = points.
Status render_svg(const Scene& scene, const RenderOptions& options,
                  const std::filesystem::path& path) {
  const View v = make_view(scene, options);
  cairo_surface_t* s = cairo_svg_surface_create(path.string().c_str(), v.width, v.height);
  if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
    const std::string why = cairo_status_to_string(cairo_surface_status(s));
    cairo_surface_destroy(s);
    return Error{path.string(), 0, "cannot write the picture: " + why};
  }
  return finish_surface(s, scene, v, options, path, false);
}

// Cairo first (it holds fontconfig objects), then fontconfig itself.
void release_render_caches() {
  cairo_debug_reset_static_data();
  FcFini();
}

// Mount positions moved into the world; ranges as reported (the ring is uncalibrated).
std::vector<SonarBeam> ring_beams(const Pose& robot, const RingLayout& layout,
                                  std::span<const double, kRingSensors> ranges,
                                  const SonarParams& params) {
  std::vector<SonarBeam> out;
  out.reserve(kRingSensors);
  for (int i = 0; i < kRingSensors; ++i) {
    SonarBeam b;
    sensor_in_world(robot, layout[i], b.origin, b.direction);
    b.half_angle = params.half_angle;
    b.range = ranges[i];
    b.max_range = params.max_range();
    b.number = layout[i].number;
    out.push_back(b);
  }
  return out;
}

// Reported pan-tilt readings are raw: undo the calibration line to draw true distances.
std::vector<SonarBeam> pan_tilt_beams(const Pose& robot, const PanTiltMount& mount,
                                      double direction, const PanTiltReading& reading,
                                      const SonarParams& params) {
  const auto m = pan_tilt_mounts(mount, direction);
  std::vector<SonarBeam> out(2);
  const double r[2] = {reading.facing, reading.opposite};
  for (int i = 0; i < 2; ++i) {
    sensor_in_world(robot, m[i], out[i].origin, out[i].direction);
    out[i].half_angle = params.half_angle;
    out[i].range = (r[i] > 0.0 && r[i] != params.no_echo) ? (r[i] - params.offset) / params.scale : 0.0;
    out[i].max_range = params.max_range();
  }
  return out;
}

}  // namespace robuter::sim
