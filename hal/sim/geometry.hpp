// SPDX-License-Identifier: GPL-3.0-or-later
// Planar geometry the simulator needs: exact unicycle arcs, segment and box tests, polygons.
#pragma once

#include <span>

#include "hal/sim/types.hpp"

namespace robuter::sim {

// How a surface reflects ultrasound (docs/SIMULATOR.md, "Surfaces"): the kind decides the
// widest incidence at which it still echoes back to the transducer.
enum class Surface : unsigned char {
  standard,  // the model's max_incidence (40°): unmarked surfaces, every shipped world
  smooth,    // specular (painted plaster, glass, metal): max_incidence_smooth (22.5°)
  rough,     // irregularities larger than half the wavelength (brick, shelving): max_incidence_rough (90°)
};
inline constexpr int kSurfaceKinds = 3;  // number of Surface values

// An obstacle edge in the world frame.
struct Segment {
  Vec2 a;                              // first end, m
  Vec2 b;                              // second end, m
  int obstacle = 0;                    // index of the obstacle the edge belongs to
  Surface surface = Surface::standard; // how the edge reflects sound (its obstacle's)
};

// An axis-aligned rectangle (in whatever frame the caller uses).
struct Box {
  Vec2 lo;  // minimum corner, m
  Vec2 hi;  // maximum corner, m
};

// sin(x)/x, accurate near 0, so arcs of any curvature (even none) share one formula.
double sinc(double x);

// Pose after moving for `t` seconds at linear speed `v` (m/s) and turn rate `w` (rad/s),
// both constant: the exact circular arc (a straight line when w = 0), not an Euler step.
Pose integrate_arc(const Pose& start, double v, double w, double t);

// Whether the segment a-b meets the closed box (Liang-Barsky clipping: exact, branch-light).
bool segment_meets_box(const Vec2& a, const Vec2& b, const Box& box);

// Whether closed segments p1-p2 and q1-q2 share a point.
bool segments_intersect(const Vec2& p1, const Vec2& p2, const Vec2& q1, const Vec2& q2);

// Whether the point lies strictly inside the polygon (even-odd rule; edges count as outside).
bool point_in_polygon(const Vec2& p, std::span<const Vec2> polygon);

// Signed area of a polygon, m² (positive when counter-clockwise).
double polygon_area(std::span<const Vec2> polygon);

// Distance from point p to segment a-b, m.
double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b);

// 2-D cross product (z of the 3-D one).
inline double cross(const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); }

}  // namespace robuter::sim
