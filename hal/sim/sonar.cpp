// SPDX-License-Identifier: GPL-3.0-or-later
// Sonar cone tracing: each nearby edge is clipped to the beam wedge, its nearest in-cone point is
// the echo candidate, and the nearest candidate with acceptable incidence that no grazing edge
// hides is the echo.
#include "hal/sim/sonar.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace robuter::sim {

namespace {

// World-frame bounding box of the beam sector (apex, both edge ends, and any axis extreme of
// the arc that falls inside the sector), from the axis (c, s) and the half-angle's cos/sin.
Box sector_box(const Vec2& o, double c, double s, double ch, double sh, double r) {
  Box b{o, o};
  auto add = [&](const Vec2& u) {
    const Vec2 p = o + r * u;
    b.lo = b.lo.cwiseMin(p);
    b.hi = b.hi.cwiseMax(p);
  };
  add({c * ch + s * sh, s * ch - c * sh});  // axis turned by -half
  add({c * ch - s * sh, s * ch + c * sh});  // axis turned by +half
  if (c >= ch) add({1.0, 0.0});
  if (-c >= ch) add({-1.0, 0.0});
  if (s >= ch) add({0.0, 1.0});
  if (-s >= ch) add({0.0, -1.0});
  return b;
}

// Clips t in [t0, t1] to where f(t) = fa + t (fb - fa) <= 0; false when nothing remains.
bool clip_half(double fa, double fb, double& t0, double& t1) {
  const double df = fb - fa;
  if (df == 0.0) return fa <= 0.0;
  const double t = -fa / df;
  if (df > 0.0) {
    t1 = std::min(t1, t);
  } else {
    t0 = std::max(t0, t);
  }
  return t0 <= t1;
}

}  // namespace

// Reserves one candidate slot per edge so tracing never allocates.
SonarModel::SonarModel(const World& world, const SonarParams& params) : world_(world) {
  candidates_.reserve(world_.segments().size());
  scratch_.prepare(world_.segments().size());
  set_params(params);
}

// Caches the trigonometry the tracer needs on every call.
void SonarModel::set_params(const SonarParams& params) {
  params_ = params;
  const double half = std::min(params_.half_angle, deg_to_rad(89.0));
  cos_half_ = std::cos(half);
  sin_half_ = std::sin(half);
  cos_max_incidence_ = std::cos(std::clamp(params_.max_incidence, 0.0, kPi / 2));
}

// Mount moved into the world frame, then the world-frame trace.
Echo SonarModel::trace(const Pose& robot, const SonarMount& mount) {
  Vec2 o;
  double d;
  sensor_in_world(robot, mount, o, d);
  return trace(o, d);
}

// In the sensor frame (x along the beam) the cone is the wedge |y| <= x·tan(half); an edge's
// in-cone part is found by clipping against the wedge's two half-planes, and its nearest point
// to the apex is the perpendicular foot when that lies in the cone (normal incidence) or else
// the in-cone end nearest the foot (least oblique in-cone point).
Echo SonarModel::trace(const Vec2& origin, double direction) {
  Echo echo;
  const double rmax = params_.max_range();
  const double c = std::cos(direction), s = std::sin(direction);
  const double ch = cos_half_, sh = sin_half_;
  const auto& segs = world_.segments();
  const Box box = sector_box(origin, c, s, ch, sh, rmax);
  const Vec2 pad = Vec2::Constant(1e-9);
  double nearest = std::numeric_limits<double>::infinity();  // nearest echoing candidate, m
  auto consider = [&](std::uint32_t i) {
    const Segment& sg = segs[i];
    const Vec2 wa = sg.a - origin, wb = sg.b - origin;
    const Vec2 a(c * wa.x() + s * wa.y(), -s * wa.x() + c * wa.y());
    const Vec2 b(c * wb.x() + s * wb.y(), -s * wb.x() + c * wb.y());
    double t0 = 0.0, t1 = 1.0;
    // Upper edge: y·cos(h) - x·sin(h) <= 0; lower edge: -y·cos(h) - x·sin(h) <= 0.
    if (!clip_half(a.y() * ch - a.x() * sh, b.y() * ch - b.x() * sh, t0, t1)) return;
    if (!clip_half(-a.y() * ch - a.x() * sh, -b.y() * ch - b.x() * sh, t0, t1)) return;
    const Vec2 ab = b - a;
    const double len2 = ab.squaredNorm();
    if (len2 <= 0.0) return;
    const double foot = -a.dot(ab) / len2;
    const double t = std::clamp(foot, t0, t1);
    const Vec2 p = a + t * ab;
    const double range = p.norm();
    if (range > rmax) return;
    double cosi = 1.0;  // cosine of the incidence angle (normal incidence at the foot)
    if (t != foot && range > 0.0) {
      const Vec2 n(-ab.y(), ab.x());
      cosi = std::min(1.0, std::abs(n.dot(p)) / (std::sqrt(len2) * range));
    }
    const bool echoes = cosi >= cos_max_incidence_;
    if (echoes) nearest = std::min(nearest, range);
    const Vec2 pw = origin + Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y());
    candidates_.push_back({range, pw, cosi, static_cast<int>(i), echoes});
  };
  // Cells are walked outwards and the walk stops once every unvisited edge is farther than the
  // nearest echoing candidate (or than the time-out range): nearer edges, the only ones that
  // could hide that candidate, have all been seen. Should that candidate turn out hidden, the
  // whole sector is walked again.
  candidates_.clear();
  const Vec2 n1(-(s * ch + c * sh), c * ch - s * sh);  // outward normal of the +half edge
  const Vec2 n2(s * ch - c * sh, -(c * ch + s * sh));   // outward normal of the -half edge
  const auto& grid = world_.grid();
  const double reached = grid.for_each_in_wedge(
      origin, box.lo - pad, box.hi + pad, n1, n2, rmax + 1e-9, scratch_, consider,
      [&](double bound) { return nearest <= bound || bound > rmax; });
  // Take echoing candidates nearest first; one is hidden when a nearer non-echoing (grazing)
  // edge crosses the line of sight to it.
  for (bool complete = !(reached < rmax);;) {
    Candidate* best = nullptr;
    for (auto& cd : candidates_) {
      if (cd.echoes && (best == nullptr || cd.range < best->range)) best = &cd;
    }
    if (best == nullptr || (!complete && best->range > reached)) {
      if (complete) return echo;
      // The walk stopped early but its nearest candidate was hidden: walk everything.
      complete = true;
      nearest = std::numeric_limits<double>::infinity();
      candidates_.clear();
      grid.for_each_in_wedge(origin, box.lo - pad, box.hi + pad, n1, n2, rmax + 1e-9, scratch_,
                             consider, [](double) { return false; });
      continue;
    }
    const Vec2 dir = (best->point - origin) / std::max(best->range, 1e-12);
    const Vec2 end = origin + std::max(best->range - 1e-7, 0.0) * dir;
    bool hidden = false;
    for (const auto& cd : candidates_) {
      if (cd.echoes || cd.range >= best->range) continue;
      const Segment& sg = segs[cd.segment];
      if (segments_intersect(origin, end, sg.a, sg.b)) {
        hidden = true;
        break;
      }
    }
    if (hidden) {
      best->echoes = false;
      continue;
    }
    if (best->range < params_.min_range) return echo;  // blinded by a too-near surface
    echo.found = true;
    echo.range = best->range;
    echo.point = best->point;
    echo.incidence = best->cos_incidence >= 1.0 ? 0.0 : std::acos(best->cos_incidence);
    echo.segment = best->segment;
    return echo;
  }
}

// Mount moved into the world frame, then the world-frame measurement.
double SonarModel::measure(const Pose& robot, const SonarMount& mount, Rng* rng) {
  Vec2 o;
  double d;
  sensor_in_world(robot, mount, o, d);
  return measure_from(o, d, rng);
}

// Order of the random effects: a drop-out loses the echo, a spurious echo replaces the reading
// by a uniform draw between min_range and the true range (or max range), noise perturbs the rest;
// a perturbed range beyond the time-out is no echo; finally the calibration line applies.
double SonarModel::measure_from(const Vec2& origin, double direction, Rng* rng) {
  const Echo e = trace(origin, direction);
  const double rmax = params_.max_range();
  double r = e.found ? e.range : -1.0;
  if (rng != nullptr) {
    if (rng->chance(params_.dropout_probability)) return params_.no_echo;
    if (rng->chance(params_.spurious_probability)) {
      const double hi = e.found ? e.range : rmax;
      r = rng->uniform(std::min(params_.min_range, hi), hi);
    } else if (e.found && (params_.noise_sigma > 0.0 || params_.noise_relative > 0.0)) {
      const double sigma = std::hypot(params_.noise_sigma, params_.noise_relative * e.range);
      r = std::max(0.0, e.range + sigma * rng->normal());
    }
  }
  if (r < 0.0 || r > rmax) return params_.no_echo;
  return params_.scale * params_.ranging_scale() * r + params_.offset;
}

}  // namespace robuter::sim
