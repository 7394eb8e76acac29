// SPDX-License-Identifier: GPL-3.0-or-later
// The room a turn in place leaves: the grown body's radius per bearing against the cells near the axle.
#include "modules/planner/lib/turn_room.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace robuter::plan {
namespace {

using Vec = Eigen::Vector2d;

// The body in its own frame: an axis-aligned box about the axle (x ahead, y left), m.
struct Box {
  Vec lo;  // m, rear right corner
  Vec hi;  // m, front left corner
};

Box box_of(const RectangleFootprint& b) {
  const double half_l = 0.5 * b.length + b.margin, half_w = 0.5 * b.width + b.margin;
  return {{b.center_offset - half_l, -half_w}, {b.center_offset + half_l, half_w}};
}

double point_box_distance(const Vec& p, const Box& box) { return (p - p.cwiseMax(box.lo).cwiseMin(box.hi)).norm(); }

double point_segment_distance(const Vec& p, const Vec& a, const Vec& b) {
  const Vec ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

// Why: the square's and the box's projections overlap on `axis` (separating-axis test).
bool overlap_on(const Vec& axis, const std::array<Vec, 4>& sq, const Box& box) {
  double s_lo = std::numeric_limits<double>::infinity(), s_hi = -s_lo;
  for (const Vec& p : sq) {
    s_lo = std::min(s_lo, axis.dot(p));
    s_hi = std::max(s_hi, axis.dot(p));
  }
  const double c = axis.dot(0.5 * (box.lo + box.hi));
  const Vec half = 0.5 * (box.hi - box.lo);
  const double r = std::abs(axis.x()) * half.x() + std::abs(axis.y()) * half.y();
  return s_hi > c - r && s_lo < c + r;
}

// Why: distance between the cell square (corners in order, body frame) and the body box: 0 when
// no edge direction separates them, else the least vertex-to-edge distance either way.
double square_box_distance(const std::array<Vec, 4>& sq, const Box& box) {
  const Vec u = (sq[1] - sq[0]).normalized(), v = (sq[3] - sq[0]).normalized();
  if (overlap_on(Vec::UnitX(), sq, box) && overlap_on(Vec::UnitY(), sq, box) && overlap_on(u, sq, box) &&
      overlap_on(v, sq, box))
    return 0.0;
  double d = std::numeric_limits<double>::infinity();
  for (const Vec& p : sq) d = std::min(d, point_box_distance(p, box));
  const std::array<Vec, 4> corners{box.lo, Vec{box.hi.x(), box.lo.y()}, box.hi, Vec{box.lo.x(), box.hi.y()}};
  for (const Vec& c : corners)
    for (int i = 0; i < 4; ++i) d = std::min(d, point_segment_distance(c, sq[i], sq[(i + 1) % 4]));
  return d;
}

}  // namespace

TurnEnvelope::TurnEnvelope(const RectangleFootprint& body, double clearance)
    : body_(body), clearance_(std::max(clearance, 0.0)) {
  const Box box = box_of(body_);
  const std::array<Vec, 4> corners{box.lo, Vec{box.hi.x(), box.lo.y()}, box.hi, Vec{box.lo.x(), box.hi.y()}};
  reach_ = 0.0;
  for (const Vec& c : corners) reach_ = std::max(reach_, c.norm() + clearance_);
  // A bin's largest radius: at one of its ends, or at a corner's bearing inside it (the grown
  // box's radius has its local maxima there, |corner| + clearance, and nowhere else).
  const double width = 2.0 * kPi / kBins;
  double prev = radius(0.0);
  for (int i = 0; i < kBins; ++i) {
    const double next = radius((i + 1) * width);
    double m = std::max(prev, next);
    for (const Vec& c : corners) {
      const double a = wrap_angle(std::atan2(c.y(), c.x()), 2.0 * kPi);
      if (a >= i * width && a <= (i + 1) * width) m = std::max(m, c.norm() + clearance_);
    }
    bin_max_[static_cast<std::size_t>(i)] = m + 1e-9;
    prev = next;
  }
  for (int b = 0; b < kBins / kBlock; ++b)
    for (int i = 0; i < kBlock; ++i)
      block_max_[static_cast<std::size_t>(b)] =
          std::max(block_max_[static_cast<std::size_t>(b)], bin_max_[static_cast<std::size_t>(b * kBlock + i)]);
}

double TurnEnvelope::max_over(int first, int count) const {
  if (count >= kBins) return reach_ + 1e-9;
  double m = 0.0;
  int i = first % kBins;
  while (count > 0) {
    if (i % kBlock == 0 && count >= kBlock) {
      m = std::max(m, block_max_[static_cast<std::size_t>(i / kBlock)]);
      i += kBlock;
      count -= kBlock;
    } else {
      m = std::max(m, bin_max_[static_cast<std::size_t>(i)]);
      ++i;
      --count;
    }
    if (i == kBins) i = 0;
  }
  return m;
}

double TurnEnvelope::radius(double angle) const {
  // The grown box is convex and holds the axle: the distance to the box grows along the ray
  // once outside it, so bisect for where it reaches the clearance.
  const Box box = box_of(body_);
  const Vec u{std::cos(angle), std::sin(angle)};
  double lo = 0.0, hi = reach_ + 1.0;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (point_box_distance(mid * u, box) <= clearance_ ? lo : hi) = mid;
  }
  return hi;
}

bool TurnEnvelope::turn_is_clear(const OccupancyMap& map, const Pose2& pose, double target) const {
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.heading) || !std::isfinite(target))
    return false;
  const double th_lo = std::min(pose.heading, target), th_hi = std::max(pose.heading, target);
  const double width = 2.0 * kPi / kBins;
  const double r = map.resolution();
  const double far = reach_ + r;
  const Cell lo = map.cell_of({pose.x - far, pose.y - far}), hi = map.cell_of({pose.x + far, pose.y + far});
  const Vec axle{pose.x, pose.y};
  for (int y = std::max(lo.y, 0); y <= std::min(hi.y, map.height() - 1); ++y)
    for (int x = std::max(lo.x, 0); x <= std::min(hi.x, map.width() - 1); ++x) {
      const Cell c{x, y};
      if (map.state(c) != CellState::Occupied) continue;
      const Point2 m = map.center(c);
      const Vec sq_lo{m.x - 0.5 * r, m.y - 0.5 * r}, sq_hi{m.x + 0.5 * r, m.y + 0.5 * r};
      const double rho = (axle.cwiseMax(sq_lo).cwiseMin(sq_hi) - axle).norm();  // nearest point of the square
      if (rho >= reach_) continue;               // beyond the grown body at every heading
      if (rho <= 0.0) return false;              // the axle's own cell
      // The bearings the square spans from the axle, about its centre's bearing.
      const Vec to_c = Vec{m.x, m.y} - axle;
      const double phi = std::atan2(to_c.y(), to_c.x());
      double b_lo = 0.0, b_hi = 0.0;
      for (const Vec& k : {sq_lo, Vec{sq_hi.x(), sq_lo.y()}, sq_hi, Vec{sq_lo.x(), sq_hi.y()}}) {
        const Vec d = k - axle;
        const double b = std::remainder(std::atan2(d.y(), d.x()) - phi, 2.0 * kPi);
        b_lo = std::min(b_lo, b);
        b_hi = std::max(b_hi, b);
      }
      // Body-frame bearings the square takes over the turn: [phi + b_lo - th_hi, phi + b_hi - th_lo].
      const double a0 = wrap_angle(phi + b_lo - th_hi, 2.0 * kPi);
      const double span = (b_hi - b_lo) + (th_hi - th_lo);
      const int first = static_cast<int>(std::floor(a0 / width));
      const int count = span >= 2.0 * kPi ? kBins : static_cast<int>(std::floor((a0 + span) / width)) - first + 1;
      if (max_over(first, count) > rho) return false;
    }
  return true;
}

double body_cell_distance(const OccupancyMap& map, const RectangleFootprint& body, const Pose2& pose, Cell cell) {
  const double r = map.resolution();
  const Point2 c = map.center(cell);
  const Eigen::Rotation2Dd to_body(-pose.heading);
  const Vec centre = to_body * Vec{c.x - pose.x, c.y - pose.y};
  const Vec ex = to_body * Vec{0.5 * r, 0.0}, ey = to_body * Vec{0.0, 0.5 * r};
  return square_box_distance({centre - ex - ey, centre + ex - ey, centre + ex + ey, centre - ex + ey}, box_of(body));
}

}  // namespace robuter::plan
