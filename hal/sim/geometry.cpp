// SPDX-License-Identifier: GPL-3.0-or-later
// Planar geometry: exact arcs, Liang-Barsky clipping, segment intersection, polygon tests.
#include "hal/sim/geometry.hpp"

#include <algorithm>
#include <cmath>

namespace robuter::sim {

// Taylor series below 1e-4 keeps full precision where sin(x)/x would cancel.
double sinc(double x) {
  if (std::abs(x) < 1e-4) {
    const double x2 = x * x;
    return 1.0 - x2 / 6.0 + x2 * x2 / 120.0;
  }
  return std::sin(x) / x;
}

// The chord of the arc has length v·t·sinc(w·t/2) and points along the mean heading.
Pose integrate_arc(const Pose& start, double v, double w, double t) {
  const double dtheta = w * t;
  const double half = 0.5 * dtheta;
  const double chord = v * t * sinc(half);
  const double mid = start.theta + half;
  return {start.x + chord * std::cos(mid), start.y + chord * std::sin(mid),
          wrap_angle(start.theta + dtheta)};
}

// Clips the parameter interval [0, 1] against the four slabs; meets when it stays non-empty.
bool segment_meets_box(const Vec2& a, const Vec2& b, const Box& box) {
  double t0 = 0.0, t1 = 1.0;
  const double d[2] = {b.x() - a.x(), b.y() - a.y()};
  const double s[2] = {a.x(), a.y()};
  const double lo[2] = {box.lo.x(), box.lo.y()};
  const double hi[2] = {box.hi.x(), box.hi.y()};
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0.0) {
      if (s[k] < lo[k] || s[k] > hi[k]) return false;
      continue;
    }
    double ta = (lo[k] - s[k]) / d[k];
    double tb = (hi[k] - s[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

namespace {
// Which side of line p-q the point r lies on: +1 left, -1 right, 0 on it.
int orientation(const Vec2& p, const Vec2& q, const Vec2& r) {
  const double v = cross(q - p, r - p);
  if (v > 0.0) return 1;
  if (v < 0.0) return -1;
  return 0;
}

// For collinear p, q, r: whether r lies within the bounding box of p-q.
bool on_segment(const Vec2& p, const Vec2& q, const Vec2& r) {
  return r.x() >= std::min(p.x(), q.x()) && r.x() <= std::max(p.x(), q.x()) &&
         r.y() >= std::min(p.y(), q.y()) && r.y() <= std::max(p.y(), q.y());
}
}  // namespace

// The classic orientation test, with the collinear cases handled.
bool segments_intersect(const Vec2& p1, const Vec2& p2, const Vec2& q1, const Vec2& q2) {
  const int o1 = orientation(p1, p2, q1), o2 = orientation(p1, p2, q2);
  const int o3 = orientation(q1, q2, p1), o4 = orientation(q1, q2, p2);
  if (o1 != o2 && o3 != o4) return true;
  if (o1 == 0 && on_segment(p1, p2, q1)) return true;
  if (o2 == 0 && on_segment(p1, p2, q2)) return true;
  if (o3 == 0 && on_segment(q1, q2, p1)) return true;
  if (o4 == 0 && on_segment(q1, q2, p2)) return true;
  return false;
}

// Counts crossings of a ray towards +x; an odd count means inside.
bool point_in_polygon(const Vec2& p, std::span<const Vec2> polygon) {
  bool inside = false;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

// Shoelace formula.
double polygon_area(std::span<const Vec2> polygon) {
  double sum = 0.0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) sum += cross(polygon[j], polygon[i]);
  return 0.5 * sum;
}

// Projects p on the segment's line and clamps to its ends.
double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  double t = len2 > 0.0 ? (p - a).dot(ab) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return (a + t * ab - p).norm();
}

}  // namespace robuter::sim
