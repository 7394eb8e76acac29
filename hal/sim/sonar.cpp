// SPDX-License-Identifier: GPL-3.0-or-later
// Sonar cone tracing: each nearby edge is clipped to the beam wedge, its nearest in-cone point is
// the echo candidate, and the nearest candidate with acceptable incidence that no grazing edge
// hides is the echo; multipath and cross-talk follow specular bounces by the image method.
#include "hal/sim/sonar.hpp"

#include <algorithm>
#include <array>
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

// The mirror image of point p across the line through a with unit normal n.
Vec2 mirror(const Vec2& p, const Vec2& a, const Vec2& n) { return p - 2.0 * n.dot(p - a) * n; }

// Unit normal of edge a-b pointing to p's side (p on the line: either).
Vec2 normal_towards(const Vec2& a, const Vec2& b, const Vec2& p) {
  const Vec2 t = (b - a).normalized();
  const Vec2 n(-t.y(), t.x());
  return n.dot(p - a) < 0.0 ? Vec2(-n) : n;
}

// Whether point p lies inside the cone of apex o, unit axis u and half-angle cosine ch.
bool in_cone(const Vec2& o, const Vec2& u, double ch, const Vec2& p) {
  const Vec2 v = p - o;
  return v.dot(u) >= ch * v.norm();
}

// At most this many transducers fired together are looked at for cross-talk (a node has 4).
constexpr std::size_t kMaxFiring = 8;

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
  const auto cos_of = [](double a) { return std::cos(std::clamp(a, 0.0, kPi / 2)); };
  cos_max_incidence_[static_cast<std::size_t>(Surface::standard)] = cos_of(params_.max_incidence);
  cos_max_incidence_[static_cast<std::size_t>(Surface::smooth)] = cos_of(params_.max_incidence_smooth);
  cos_max_incidence_[static_cast<std::size_t>(Surface::rough)] = cos_of(params_.max_incidence_rough);
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
Echo SonarModel::trace(const Vec2& origin, double direction) { return trace_beyond(origin, direction, nullptr); }

// As trace(); with `beyond`, each edge is also clipped to the mirror's real side.
Echo SonarModel::trace_beyond(const Vec2& origin, double direction, const Beyond* beyond) {
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
    double t0 = 0.0, t1 = 1.0;
    if (beyond != nullptr) {
      if (static_cast<int>(i) == beyond->skip) return;
      // Beyond the mirror: normal · (p − point) >= 0, i.e. f(t) = −normal · (p(t) − point) <= 0.
      if (!clip_half(-beyond->normal.dot(sg.a - beyond->point), -beyond->normal.dot(sg.b - beyond->point), t0, t1)) return;
    }
    const Vec2 wa = sg.a - origin, wb = sg.b - origin;
    const Vec2 a(c * wa.x() + s * wa.y(), -s * wa.x() + c * wa.y());
    const Vec2 b(c * wb.x() + s * wb.y(), -s * wb.x() + c * wb.y());
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
    const bool echoes = cosi >= cos_max_incidence_[static_cast<std::size_t>(sg.surface)];
    if (echoes) nearest = std::min(nearest, range);
    const Vec2 pw = origin + Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y());
    candidates_.push_back({range, pw, cosi, static_cast<int>(i), echoes, !echoes});
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

double SonarModel::measure_from(const Vec2& origin, double direction, Rng* rng) {
  return report(arrival(origin, direction, {}, {}), rng);
}

// Every arrival first (tracing draws nothing), then the random effects sensor by sensor, so a
// firing of one draws what measure() draws. Beyond kMaxFiring, transducers hear no node-mates.
void SonarModel::measure_firing(const Pose& robot, std::span<const SonarMount> mounts,
                                std::span<double> out, Rng* rng) {
  const std::size_t n = std::min(mounts.size(), out.size());
  if (!params_.crosstalk || n > kMaxFiring) {
    for (std::size_t i = 0; i < n; ++i) {
      Vec2 o;
      double d;
      sensor_in_world(robot, mounts[i], o, d);
      out[i] = arrival(o, d, {}, {});
    }
  } else {
    // Each sensor placed once; sensor i's mates are the others, gathered in front of the span.
    std::array<Vec2, kMaxFiring> origins, axes;
    std::array<double, kMaxFiring> directions{};
    for (std::size_t i = 0; i < n; ++i) {
      sensor_in_world(robot, mounts[i], origins[i], directions[i]);
      axes[i] = Vec2(std::cos(directions[i]), std::sin(directions[i]));
    }
    std::array<Vec2, kMaxFiring> mate_o, mate_a;
    for (std::size_t i = 0; i < n; ++i) {
      std::size_t m = 0;
      for (std::size_t j = 0; j < n; ++j) {
        if (j == i) continue;
        mate_o[m] = origins[j];
        mate_a[m++] = axes[j];
      }
      out[i] = arrival(origins[i], directions[i], std::span<const Vec2>(mate_o.data(), m),
                       std::span<const Vec2>(mate_a.data(), m));
    }
  }
  for (std::size_t i = 0; i < n; ++i) out[i] = report(out[i], rng);
}

// Cross-talk (Borenstein & Koren 1995, fig. 1): a node-mate's sound reaches this transducer by
// a specular bounce off an edge its own beam met, when the bounce point lies in both cones; the
// path runs from the mate's image across that edge. Multipath (Kuc & Siegel 1987; Wilkes et al.
// 1990): the nearest surface the beam meets too obliquely to echo reflects it; the transducer's
// image across that surface looks on, and an echo at normal incidence beyond the surface comes
// back the same way. Both only where they arrive first. Occlusion of these paths is not checked.
double SonarModel::arrival(const Vec2& origin, double direction, std::span<const Vec2> mate_origins,
                           std::span<const Vec2> mate_axes) {
  const Echo e = trace_beyond(origin, direction, nullptr);
  double first = e.found ? e.range : std::numeric_limits<double>::infinity();
  const auto& segs = world_.segments();
  const Vec2 axis(std::cos(direction), std::sin(direction));
  // Cross-talk, cheapest tests first: the mate on this side of the edge, its image's path no
  // longer than the first arrival so far, the bounce point on the edge, inside both cones.
  for (std::size_t ci = 0; !mate_origins.empty() && ci < candidates_.size(); ++ci) {
    const Segment& sg = segs[static_cast<std::size_t>(candidates_[ci].segment)];
    const Vec2 n = normal_towards(sg.a, sg.b, origin);
    const double dy = n.dot(origin - sg.a);  // this transducer's distance from the edge's line
    if (dy <= 0.0) continue;
    const Vec2 ab = sg.b - sg.a;
    for (std::size_t k = 0; k < mate_origins.size(); ++k) {
      const double dx = n.dot(mate_origins[k] - sg.a);
      if (dx <= 0.0) continue;  // the mate on the other side
      const Vec2 image = mirror(mate_origins[k], sg.a, n);
      const double path2 = (image - origin).squaredNorm();
      if (path2 >= 4.0 * first * first || path2 < 4.0 * params_.min_range * params_.min_range) continue;
      const Vec2 bounce = origin + (dy / (dy + dx)) * (image - origin);
      const double u = (bounce - sg.a).dot(ab);
      if (u < 0.0 || u > ab.squaredNorm()) continue;  // off the edge
      if (!in_cone(origin, axis, cos_half_, bounce) || !in_cone(mate_origins[k], mate_axes[k], cos_half_, bounce)) continue;
      first = 0.5 * std::sqrt(path2);
    }
  }
  if (params_.multipath) {
    const Candidate* grazing = nullptr;
    for (const auto& cd : candidates_) {
      if (cd.grazing && cd.range < first && cd.range >= params_.min_range && (grazing == nullptr || cd.range < grazing->range)) grazing = &cd;
    }
    if (grazing != nullptr) {
      const Segment& sg = segs[static_cast<std::size_t>(grazing->segment)];
      const Vec2 n = normal_towards(sg.a, sg.b, origin);
      const Vec2 image = mirror(origin, sg.a, n);
      const Vec2 image_axis = axis - 2.0 * n.dot(axis) * n;
      const Beyond real_side{sg.a, n, grazing->segment};
      const Echo back = trace_beyond(image, std::atan2(image_axis.y(), image_axis.x()), &real_side);
      // The path back must bounce off the edge itself, not off its line beyond the edge.
      if (back.found && back.range < first && segments_intersect(image, back.point, sg.a, sg.b)) first = back.range;
    }
  }
  return std::isfinite(first) && first <= params_.max_range() ? first : -1.0;
}

// Order of the random effects: a drop-out loses the echo; a spurious echo replaces the reading —
// by a uniform draw between min_range and the true range (or max range), or, with
// spurious_in_window, by a noise pulse at a uniform time of the window when it comes before the
// echo; noise perturbs the rest; a range beyond the time-out is no echo; then the calibration.
double SonarModel::report(double range, Rng* rng) {
  const double rmax = params_.max_range();
  const bool found = range >= 0.0;
  auto reported = [&](double r) {
    if (r < 0.0 || r > rmax) return params_.no_echo;
    return params_.scale * params_.ranging_scale() * r + params_.offset;
  };
  if (rng == nullptr) return reported(range);
  if (rng->chance(params_.dropout_probability)) return params_.no_echo;
  if (rng->chance(params_.spurious_probability)) {
    if (!params_.spurious_in_window) {
      const double hi = found ? range : rmax;
      return reported(rng->uniform(std::min(params_.min_range, hi), hi));
    }
    const double pulse = rng->uniform(params_.min_range, rmax);
    if (!found || pulse < range) return reported(pulse);
  }
  if (found && (params_.noise_sigma > 0.0 || params_.noise_relative > 0.0)) {
    const double sigma = std::hypot(params_.noise_sigma, params_.noise_relative * range);
    return reported(std::max(0.0, range + sigma * rng->normal()));
  }
  return reported(range);
}

}  // namespace robuter::sim
