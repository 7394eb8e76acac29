// SPDX-License-Identifier: GPL-3.0-or-later
// Cairo renderer: the scene's layers on the plot, then its labels, title, axes, scale bar and legend.
#include "hal/sim/render.hpp"

#include <cmath>

#include "picture/page.hpp"

namespace robuter::sim {

namespace {

using picture::Ink;
using picture::Rgb;
using picture::Swatch;

constexpr Rgb kFloor{1.0, 1.0, 1.0};
const Ink kGrid{{0.90, 0.90, 0.92}, Swatch::line, "grid, 1 m", 1.0, 1.0};
const Ink kObstacle{{0.55, 0.55, 0.58}, Swatch::fill, "obstacle"};
const Ink kObstacleSmooth{{0.55, 0.70, 0.85}, Swatch::fill, "obstacle, smooth surface (specular)"};
const Ink kObstacleRough{{0.75, 0.55, 0.40}, Swatch::fill, "obstacle, rough surface (diffuse)"};
const Ink kWall{{0.20, 0.20, 0.22}, Swatch::line, "obstacle edge, thin wall", 1.0, 2.5};
const Ink kDoor{{0.10, 0.60, 0.20}, Swatch::dashed, "door (name, width)"};
const Ink kRobot{{0.55, 0.70, 0.95}, Swatch::fill, "robot at its true pose", 0.85};
const Ink kRobotEdge{{0.05, 0.15, 0.45}, Swatch::line, "robot edge, wheels, heading", 1.0, 1.5};
const Ink kStart{{0.05, 0.15, 0.45}, Swatch::dashed, "start pose", 0.6, 1.0};
const Ink kTrail{{0.75, 0.05, 0.35}, Swatch::line, "trail (where the robot went)"};
const Ink kBeam{{0.95, 0.75, 0.10}, Swatch::fill, "ring sonar: cone to its echo", 0.5};
const Ink kBeamSilent{{0.95, 0.75, 0.10}, Swatch::dotted, "ring sonar: no echo (to time-out)", 0.6, 1.0};
const Ink kPanTilt{{0.70, 0.10, 0.70}, Swatch::fill, "pan-tilt sonar: cone to its echo", 0.5};
const Ink kPanTiltSilent{{0.70, 0.10, 0.70}, Swatch::dotted, "pan-tilt sonar: no echo", 0.6, 1.0};
const Ink kGoal{{0.85, 0.10, 0.10}, Swatch::cross, "goal"};
const Ink kMarker{{0.85, 0.10, 0.10}, Swatch::line, "marker (named pose)", 1.0, 1.5};

// What every drawing step needs: the context, the page, the inks used and the labels wished.
struct Pen {
  cairo_t* cr;                     // where to draw
  const View& v;                   // the page
  picture::Legend& legend;         // inks used so far
  std::vector<picture::Label>& labels;  // labels to place at the end
  bool with_labels;                // names and numbers wanted

  void use(const Ink& ink, double alpha = 1.0) { legend.use(cr, ink, alpha); }
  void move(const Vec2& w) {
    const Vec2 d = v.to_device(w);
    cairo_move_to(cr, d.x(), d.y());
  }
  void line(const Vec2& w) {
    const Vec2 d = v.to_device(w);
    cairo_line_to(cr, d.x(), d.y());
  }
  void label(const Vec2& w, std::string text, double size = 11.0) {
    if (with_labels) labels.push_back({v.to_device(w), std::move(text), size});
  }
  void dash(double on, double off) {
    const double d[] = {on, off};
    cairo_set_dash(cr, d, 2, 0.0);
  }
  void no_dash() { cairo_set_dash(cr, nullptr, 0, 0.0); }
};

// A cone (wedge) from `o` along `dir`, half-angle `half`, radius `r` m; device y points down,
// so world angle a becomes −a.
void wedge(Pen& p, const Vec2& o, double dir, double half, double r) {
  const Vec2 d = p.v.to_device(o);
  cairo_move_to(p.cr, d.x(), d.y());
  cairo_arc(p.cr, d.x(), d.y(), r * p.v.scale, -(dir + half), -(dir - half));
  cairo_close_path(p.cr);
}

// A light 1 m grid, to read distances off the picture.
void draw_grid(Pen& p) {
  p.use(kGrid);
  cairo_set_line_width(p.cr, 1.0);
  for (double x = std::ceil(p.v.lo.x()); x <= p.v.hi.x(); x += 1.0) {
    p.move({x, p.v.lo.y()});
    p.line({x, p.v.hi.y()});
  }
  for (double y = std::ceil(p.v.lo.y()); y <= p.v.hi.y(); y += 1.0) {
    p.move({p.v.lo.x(), y});
    p.line({p.v.hi.x(), y});
  }
  cairo_stroke(p.cr);
}

// Obstacles filled grey (blue-grey when smooth, brown when rough) with a dark outline; thin (two-vertex) walls as thick lines.
void draw_obstacles(Pen& p, const World& w) {
  for (const auto& ob : w.obstacles()) {
    const auto& v = ob.vertices;
    if (v.size() < 2) continue;
    p.move(v[0]);
    for (std::size_t i = 1; i < v.size(); ++i) p.line(v[i]);
    if (v.size() >= 3) {
      cairo_close_path(p.cr);
      p.use(ob.surface == Surface::smooth  ? kObstacleSmooth
            : ob.surface == Surface::rough ? kObstacleRough
                                           : kObstacle);
      cairo_fill_preserve(p.cr);
    }
    p.use(kWall);
    cairo_set_line_width(p.cr, v.size() >= 3 ? 1.0 : 2.5);
    cairo_stroke(p.cr);
  }
}

// Doors: a dashed green line across the opening, named with its width.
void draw_doors(Pen& p, const World& w) {
  for (const auto& d : w.doors) {
    const Vec2 u(std::cos(d.wall_direction), std::sin(d.wall_direction));
    p.use(kDoor);
    cairo_set_line_width(p.cr, 2.0);
    p.dash(4.0, 3.0);
    p.move(d.centre - 0.5 * d.width * u);
    p.line(d.centre + 0.5 * d.width * u);
    cairo_stroke(p.cr);
    p.no_dash();
    p.label(d.centre, d.name + " " + std::to_string(static_cast<int>(std::lround(d.width * 100))) + " cm");
  }
}

// The body's outline at a pose.
void body_path(Pen& p, const RobotGeometry& g, const Pose& pose) {
  Vec2 c[4];
  footprint_corners(g, pose, c);
  p.move(c[0]);
  for (int i = 1; i < 4; ++i) p.line(c[i]);
  cairo_close_path(p.cr);
}

// A small arrow for a pose, `len` m long.
void pose_arrow(Pen& p, const Pose& pose, double len, const Ink& ink) {
  const Vec2 o(pose.x, pose.y);
  const Vec2 u = heading_vector(pose);
  const Vec2 n(-u.y(), u.x());
  p.use(ink);
  cairo_set_line_width(p.cr, 1.5);
  p.move(o);
  p.line(o + len * u);
  cairo_stroke(p.cr);
  p.move(o + len * u);
  p.line(o + 0.7 * len * u + 0.15 * len * n);
  p.line(o + 0.7 * len * u - 0.15 * len * n);
  cairo_close_path(p.cr);
  cairo_fill(p.cr);
}

// Start pose (dashed body outline), goal (red cross) and named markers (arrows).
void draw_marks(Pen& p, const Scene& s) {
  const World& w = *s.world;
  if (w.start) {
    body_path(p, s.geometry, *w.start);
    p.use(kStart, 0.6);
    cairo_set_line_width(p.cr, 1.0);
    p.dash(3.0, 3.0);
    cairo_stroke(p.cr);
    p.no_dash();
    p.label({w.start->x, w.start->y}, "start");
  }
  if (w.goal) {
    const Vec2 d = p.v.to_device(*w.goal);
    p.use(kGoal);
    cairo_set_line_width(p.cr, 2.5);
    cairo_move_to(p.cr, d.x() - 7, d.y() - 7);
    cairo_line_to(p.cr, d.x() + 7, d.y() + 7);
    cairo_move_to(p.cr, d.x() - 7, d.y() + 7);
    cairo_line_to(p.cr, d.x() + 7, d.y() - 7);
    cairo_stroke(p.cr);
    p.label(*w.goal, "goal");
  }
  for (const auto& m : w.markers) {
    pose_arrow(p, m.pose, 0.3, kMarker);
    p.label({m.pose.x, m.pose.y}, m.name, 10.0);
  }
}

// Where the robot has been, as one polyline.
void draw_trail(Pen& p, const Trail& t) {
  if (t.size() < 2) return;
  p.use(kTrail);
  cairo_set_line_width(p.cr, 2.0);
  p.move(t[0]);
  for (std::size_t i = 1; i < t.size(); ++i) p.line(t[i]);
  cairo_stroke(p.cr);
}

// Echoing beams: a translucent cone to the echo and a bold arc at the range; silent beams: a
// thin dotted axis to the time-out range. Sensor numbers just outside the transducer.
void draw_beams(Pen& p, const std::vector<SonarBeam>& beams, const Ink& echo, const Ink& silent, bool cones) {
  for (const auto& b : beams) {
    const Vec2 u(std::cos(b.direction), std::sin(b.direction));
    if (b.range > 0.0) {
      if (cones && b.half_angle > 0.0) {
        wedge(p, b.origin, b.direction, b.half_angle, b.range);
        p.use(echo, 0.18);
        cairo_fill(p.cr);
        const Vec2 d = p.v.to_device(b.origin);
        cairo_new_sub_path(p.cr);
        cairo_arc(p.cr, d.x(), d.y(), b.range * p.v.scale, -(b.direction + b.half_angle), -(b.direction - b.half_angle));
        p.use(echo, 0.95);
        cairo_set_line_width(p.cr, 2.0);
        cairo_stroke(p.cr);
      }
      p.use(echo, 0.8);
      cairo_set_line_width(p.cr, 1.0);
      p.move(b.origin);
      p.line(b.origin + b.range * u);
      cairo_stroke(p.cr);
    } else {
      p.use(silent, 0.45);
      cairo_set_line_width(p.cr, 0.8);
      p.dash(2.0, 4.0);
      p.move(b.origin);
      p.line(b.origin + b.max_range * u);
      cairo_stroke(p.cr);
      p.no_dash();
    }
    if (b.number > 0) p.label(b.origin + 0.1 * u, std::to_string(b.number), 9.0);
  }
}

// The robot: filled body, wheels at the axle, heading arrow.
void draw_robot(Pen& p, const RobotGeometry& g, const Pose& pose) {
  body_path(p, g, pose);
  p.use(kRobot, 0.85);
  cairo_fill_preserve(p.cr);
  p.use(kRobotEdge);
  cairo_set_line_width(p.cr, 1.5);
  cairo_stroke(p.cr);
  for (const double side : {-1.0, 1.0}) {
    const double y = side * 0.5 * g.wheel_base;
    p.move(to_world(pose, {-0.1, y - 0.025}));
    p.line(to_world(pose, {0.1, y - 0.025}));
    p.line(to_world(pose, {0.1, y + 0.025}));
    p.line(to_world(pose, {-0.1, y + 0.025}));
    cairo_close_path(p.cr);
    cairo_fill(p.cr);
  }
  pose_arrow(p, pose, 0.8 * g.axle_to_front, kRobotEdge);
}

// Runs a hook on the plot, clipped to it, with the context restored after.
void hook(cairo_t* cr, const View& v, const DrawHook& h) {
  if (!h) return;
  cairo_save(cr);
  picture::clip_to_plot(cr, v);
  h(cr, v);
  cairo_restore(cr);
}

}  // namespace

// Layers, bottom to top: floor, grid, underlay, obstacles, doors, marks, beams, trail, robot,
// pan-tilt, overlay; then the words: title, axes, scale bar, legend, and last the labels (placed
// where they collide with nothing laid out before them).
picture::Layout render(cairo_t* cr, const Scene& scene, const View& view, const RenderOptions& options) {
  picture::Layout layout = view.layout();
  picture::Legend legend;
  std::vector<picture::Label> labels;
  Pen p{cr, view, legend, labels, options.labels};
  cairo_save(cr);
  cairo_set_source_rgb(cr, kFloor.r, kFloor.g, kFloor.b);
  cairo_paint(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_save(cr);
  picture::clip_to_plot(cr, view);
  if (options.grid) draw_grid(p);
  hook(cr, view, scene.underlay);
  if (scene.world != nullptr) {
    draw_obstacles(p, *scene.world);
    draw_doors(p, *scene.world);
    draw_marks(p, scene);
  }
  draw_beams(p, scene.beams, kBeam, kBeamSilent, options.cones);
  if (scene.trail != nullptr) draw_trail(p, *scene.trail);
  if (scene.robot) draw_robot(p, scene.geometry, *scene.robot);
  draw_beams(p, scene.pan_tilt, kPanTilt, kPanTiltSilent, options.cones);
  hook(cr, view, scene.overlay);
  cairo_restore(cr);
  for (const Ink& k : scene.keys) legend.add(k);
  const std::string title = !scene.title.empty() ? scene.title : scene.world != nullptr ? scene.world->name : "simulated world";
  picture::draw_words(cr, view, title, legend, labels, layout);
  cairo_restore(cr);
  return layout;
}

}  // namespace robuter::sim
