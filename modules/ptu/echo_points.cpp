// SPDX-License-Identifier: GPL-3.0-or-later
// Echo localisation (runs of equal ranges, farther neighbours) and odometric carrying of points.
#include "modules/ptu/echo_points.hpp"
#include "robot/robot_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace robuter::ptu {

EchoGeometry echo_geometry(const robot::RobotModel& m, std::int32_t same_echo_mm, std::int32_t far_mm) {
  EchoGeometry g;
  g.pivot_x_mm = m.pan_tilt.pivot_x * 1000.0;
  g.face_mm = m.pan_tilt.face_offset * 1000.0;
  g.beam_half_deg = m.pan_tilt.half_angle / robot::kDeg;
  g.same_echo_mm = same_echo_mm;
  g.far_mm = far_mm;
  return g;
}

double wrap_deg(double a) {
  a = std::remainder(a, 360.0);
  return a <= -180.0 ? a + 360.0 : a;
}

// Why the farther neighbours: a beam that read farther than the echo cannot contain it (the
// nearest in-beam surface is what a sonar reports), which bounds the echo on that side; a
// neighbour that read nearer may contain it behind something nearer, so it bounds nothing.
BearingInterval echo_interval(const std::array<std::int32_t, kSectors>& r, const std::array<bool, kSectors>& usable,
                              int k, const EchoGeometry& g) {
  const double h = g.beam_half_deg;
  // Neighbours that can share a point: a point lies within ±h of at most ⌈2h/5⌉ sector axes
  // (one more only on the exact boundary, which is no information anyway).
  const int reach = std::max(0, static_cast<int>(std::ceil(2.0 * h / kSectorDegrees)) - 1);
  const std::int32_t rk = r[static_cast<std::size_t>(k)];
  auto same = [&](int j) {
    const auto i = static_cast<std::size_t>(wrap_sector(j));
    return usable[i] && std::abs(r[i] - rk) <= g.same_echo_mm;
  };
  int lo = k, hi = k;
  while (hi - k < reach && same(hi + 1)) ++hi;
  while (k - lo < reach && hi - lo < reach && same(lo - 1)) --lo;
  BearingInterval b{kSectorDegrees * hi - h, kSectorDegrees * lo + h};
  auto farther = [&](int j) {
    const auto i = static_cast<std::size_t>(wrap_sector(j));
    return usable[i] && r[i] > rk + g.same_echo_mm;
  };
  if (farther(hi + 1)) b.high = std::min(b.high, kSectorDegrees * (hi + 1) - h);
  if (farther(lo - 1)) b.low = std::max(b.low, kSectorDegrees * (lo - 1) + h);
  return b;
}

void locate_echoes(const PanTiltScan& scan, const SectorPose& now, std::uint64_t now_tick, std::uint64_t max_age_ticks,
                   const EchoGeometry& g, Echoes& out) {
  std::array<bool, kSectors> usable{};
  for (std::size_t i = 0; i < usable.size(); ++i) {
    const std::uint64_t t = scan.read_tick[i];
    usable[i] = t > 0 && t <= now_tick && now_tick - t <= max_age_ticks;
  }
  const double now_th = now.theta * 0.01 * robot::kDeg;
  const double cn = std::cos(now_th), sn = std::sin(now_th);
  const double now_x = now.x * 0.1, now_y = now.y * 0.1;  // mm
  for (int k = 0; k < kSectors; ++k) {
    const auto i = static_cast<std::size_t>(k);
    Echo& e = out[i];
    e = Echo{};
    if (!usable[i]) continue;
    e.valid = true;
    e.tick = scan.read_tick[i];
    const double r = scan.raw[i];
    // The direction the reading really looked along, unwrapped next to the sector's nominal angle.
    const double axis = kSectorDegrees * k + wrap_deg(scan.direction[i] * 0.01 - kSectorDegrees * k);
    double bearing = axis;
    e.spread_deg = g.beam_half_deg;
    e.far = scan.raw[i] >= g.far_mm;
    if (!e.far) {
      // Only neighbours of the same pass can describe the same point.
      std::array<bool, kSectors> mates = usable;
      for (int d = -3; d <= 3; ++d) {
        const auto j = static_cast<std::size_t>(wrap_sector(k + d));
        const std::uint64_t tj = scan.read_tick[j];
        if (mates[j] && (tj > e.tick ? tj - e.tick : e.tick - tj) > g.run_window_ticks) mates[j] = false;
      }
      BearingInterval b = echo_interval(scan.raw, mates, k, g);
      if (b.empty()) {
        // The neighbours contradict each other: one of them lied. A neighbour that heard nothing
        // is the likelier liar (a lost echo, issue #19's realistic sonar): bound by echoes only.
        std::array<bool, kSectors> heard = mates;
        for (std::size_t j = 0; j < heard.size(); ++j) heard[j] = heard[j] && scan.raw[j] < g.far_mm;
        b = echo_interval(scan.raw, heard, k, g);
      }
      if (!b.empty()) {
        // The interval is in nominal sector angles; the firing was within a degree of them.
        const double nominal = kSectorDegrees * k;
        bearing = std::clamp(0.5 * (b.low + b.high) + (axis - nominal), axis - g.beam_half_deg, axis + g.beam_half_deg);
        e.spread_deg = std::min(g.beam_half_deg, 0.5 * (b.high - b.low) + std::abs(axis - nominal));
      }
    }
    // The point in the robot frame of the firing: from the face on the axis, along the bearing.
    const double fx = g.pivot_x_mm + g.face_mm * std::cos(axis * robot::kDeg);
    const double fy = g.face_mm * std::sin(axis * robot::kDeg);
    const double px = fx + r * std::cos(bearing * robot::kDeg), py = fy + r * std::sin(bearing * robot::kDeg);
    // Carried through the odometry frame to the current robot frame.
    const SectorPose& at = scan.pose[i];
    const double th = at.theta * 0.01 * robot::kDeg;
    const double wx = at.x * 0.1 + px * std::cos(th) - py * std::sin(th);
    const double wy = at.y * 0.1 + px * std::sin(th) + py * std::cos(th);
    const double dx = wx - now_x, dy = wy - now_y;
    e.x_mm = dx * cn + dy * sn;
    e.y_mm = -dx * sn + dy * cn;
    const double rx = e.x_mm - g.pivot_x_mm, ry = e.y_mm;
    e.bearing_deg = std::atan2(ry, rx) / robot::kDeg;
    e.range_mm = std::hypot(rx, ry) - g.face_mm;
  }
}

}  // namespace robuter::ptu
