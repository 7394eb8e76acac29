// SPDX-License-Identifier: GPL-3.0-or-later
// Swept envelope: outline samples, the arc's poses, the clear fraction from the stopping horizon.
#include "modules/emergency/swept_envelope.hpp"

#include <algorithm>
#include <cmath>

namespace robuter::emergency {

SweptEnvelope::SweptEnvelope(const EnvelopeSettings& s) : s_(s) {
  s_.step = std::max(s_.step, 0.005);
  // Offsets 0, step, 2·step … margin: the ring between the body and the grown outline is sampled
  // too, so an obstacle already inside the margin is met by the first pose that moves towards it.
  const int rings = static_cast<int>(std::ceil(s_.margin / s_.step)) + 1;
  for (int k = 0; k < rings; ++k) {
    const double o = rings == 1 ? 0.0 : s_.margin * k / (rings - 1);
    const double x0 = -s_.rear - o, x1 = s_.front + o, y0 = -s_.half_width - o, y1 = s_.half_width + o;
    auto face = [&](Eigen::Vector2d a, Eigen::Vector2d b, Eigen::Vector2d n) {
      const int m = std::max(1, static_cast<int>(std::ceil((b - a).norm() / s_.step)));
      for (int i = 0; i <= m; ++i) outline_.push_back({a + (b - a) * (static_cast<double>(i) / m), n});
    };
    face({x1, y0}, {x1, y1}, {1.0, 0.0});    // front
    face({x0, y0}, {x0, y1}, {-1.0, 0.0});   // rear
    face({x0, y1}, {x1, y1}, {0.0, 1.0});    // left
    face({x0, y0}, {x1, y0}, {0.0, -1.0});   // right
    reach_ = std::max(reach_, std::hypot(std::max(x1, -x0), y1));
  }
}

double SweptEnvelope::horizon(double k, double w, double decel) const {
  return k * s_.reaction + k * k * w / (2.0 * decel);
}

double SweptEnvelope::fraction_for(double tau, double w, double decel) const {
  if (tau <= 0.0) return 0.0;
  const double q = w / decel;
  if (q <= 1e-12) return s_.reaction > 0.0 ? tau / s_.reaction : 1.0;
  return (-s_.reaction + std::sqrt(s_.reaction * s_.reaction + 2.0 * q * tau)) / q;
}

// A point under the body now is the body; a missing certificate is a creep's where no reading could
// have looked, else missing data.
SweptEnvelope::Meets SweptEnvelope::meets(const EvidenceGrid& g, const Pose2& now, double v, double w, double tau,
                                          const Look& look, Eigen::Vector2d* where) const {
  const Pose2 pose = advance(now, v, w, tau);
  const double c = std::cos(pose.theta), sn = std::sin(pose.theta);
  const double c0 = std::cos(now.theta), s0 = std::sin(now.theta);
  Meets worst = Meets::clear;
  for (const OutlinePoint& o : outline_) {
    // Velocity of the body point in the robot frame: (v − w·y, w·x); leading when it leaves the face.
    if ((v - w * o.q.y()) * o.n.x() + w * o.q.x() * o.n.y() <= 1e-9) continue;
    const Eigen::Vector2d q = pose.p + Eigen::Vector2d(c * o.q.x() - sn * o.q.y(), sn * o.q.x() + c * o.q.y());
    const Eigen::Vector2d d = q - now.p;
    const double lx = c0 * d.x() + s0 * d.y(), ly = -s0 * d.x() + c0 * d.y();
    const Eigen::Vector2d e = s_.outside(lx, ly);
    if (e.x() == 0.0 && e.y() == 0.0) continue;  // under the body now
    const CellState st = g.state(q, look.tick, s_.free_age_ticks);
    if (st == CellState::free) continue;
    const bool near = e.x() * e.x() + e.y() * e.y() <= s_.near * s_.near;
    // No reading can refresh a certificate inside the blind near field: an older one counts there.
    if (st == CellState::stale && near && g.state(q, look.tick, look.near_age) == CellState::free) continue;
    if (st == CellState::obstacle) {
      if (where) *where = o.q;
      return Meets::obstacle;
    }
    // Blind from the start pose: a creep's. Anything else not certified is missing data (the UD1000
    // wall: when any unknown near field allowed a creep, a robot that came close to space its ring
    // had not read crept into a wall 19 mm ahead).
    const Meets m = look.blind != nullptr && look.blind->covers(q) ? Meets::near_unknown : Meets::missing;
    if (m > worst && where) *where = o.q;
    worst = std::max(worst, m);
  }
  return worst;
}

// Poses every `step` of the fastest outline point's travel; the first bad pose is refined by
// bisection against the last good one.
double SweptEnvelope::first(const EvidenceGrid& g, const Pose2& now, double v, double w, double tau_max, Meets level,
                            const Look& look, Meets& what, int& poses, Eigen::Vector2d* where) const {
  what = Meets::clear;
  const double speed = std::abs(v) + std::abs(w) * reach_;  // fastest outline point, m/s
  if (speed <= 1e-9 || tau_max <= 0.0) return tau_max + 1.0;
  const int n = std::clamp(static_cast<int>(std::ceil(tau_max * speed / s_.step)), 1, kMaxPoses);
  double good = 0.0;
  for (int i = 1; i <= n; ++i) {
    const double tau = tau_max * i / n;
    ++poses;
    const Meets m = meets(g, now, v, w, tau, look, where);
    if (m < level) {
      good = tau;
      continue;
    }
    what = m;
    double bad = tau;
    for (int r = 0; r < kRefine; ++r) {
      const double mid = 0.5 * (good + bad);
      ++poses;
      const Meets mm = meets(g, now, v, w, mid, look);
      if (mm < level) {
        good = mid;
      } else {
        bad = mid;
        what = mm;
      }
    }
    return good;
  }
  return tau_max + 1.0;
}

EnvelopeVerdict SweptEnvelope::judge(const EvidenceGrid& g, const Pose2& now, double left, double right,
                                     std::uint64_t tick, const StartBlind* blind, bool ring_alive, bool bumpers) const {
  EnvelopeVerdict out;
  const double wmax = std::max(std::abs(left), std::abs(right));
  if (wmax <= 0.0) return out;
  const double v = 0.5 * (left + right), w = (right - left) / s_.wheel_base;
  const double tau_max = horizon(1.0, wmax, s_.decel);
  // A dead ring refreshes nothing anywhere: the near field's longer life is for a ring that reads.
  const bool creep_ok = ring_alive && bumpers;
  const Look look{tick, ring_alive ? s_.near_age_ticks : s_.free_age_ticks, creep_ok ? blind : nullptr};
  // Where the request first meets anything not certified free (near field included) …
  Meets what_near = Meets::clear;
  const double tau_near = first(g, now, v, w, tau_max, Meets::near_unknown, look, what_near, out.poses, &out.where);
  if (tau_near > tau_max) return out;  // all clear: the whole request
  double k = fraction_for(tau_near, wmax, s_.decel);
  // … and where it first meets missing data or an obstacle (the near field allows a creep there).
  Meets what_hard = what_near;
  double tau_hard = tau_near;
  if (what_near == Meets::near_unknown) tau_hard = first(g, now, v, w, tau_max, Meets::missing, look, what_hard, out.poses);
  const double k_hard = tau_hard > tau_max ? 1.0 : fraction_for(tau_hard, wmax, s_.decel);
  const double creep = creep_ok ? s_.creep : 0.0;
  if (what_near == Meets::near_unknown) k = std::max(k, std::min(k_hard, creep / wmax));
  out.fraction = std::clamp(k, 0.0, 1.0);
  out.missing = what_hard == Meets::missing || what_near == Meets::near_unknown;
  // Nothing may move and what stops even a creep is obstacle evidence: a protective stop.
  const double creep_tau = horizon(std::min(1.0, std::max(creep, 0.01) / wmax), wmax, s_.decel);
  out.obstacle = what_hard == Meets::obstacle && tau_hard <= creep_tau && out.fraction * wmax < 0.01;
  return out;
}

bool SweptEnvelope::braking_meets_obstacle(const EvidenceGrid& g, const Pose2& now, double v, double w, double decel,
                                           std::uint64_t tick) const {
  const double wmax = std::max(std::abs(v - 0.5 * w * s_.wheel_base), std::abs(v + 0.5 * w * s_.wheel_base));
  if (wmax <= 1e-3) return false;
  // Braking from the current speeds: equivalent time w/(2a) at them, no reaction (the stop goes out now).
  const double tau = wmax / (2.0 * decel);
  Meets what = Meets::clear;
  int poses = 0;
  first(g, now, v, w, tau, Meets::obstacle, Look{tick, s_.near_age_ticks, nullptr}, what, poses);
  return what == Meets::obstacle;
}

}  // namespace robuter::emergency
