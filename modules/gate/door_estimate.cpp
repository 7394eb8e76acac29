// SPDX-License-Identifier: GPL-3.0-or-later
// Passage estimate: corner lock, wall fit by a search over the normal, edges on the wall line.
#include "modules/gate/door_estimate.hpp"
#include "robot/robot_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace robuter::gate {

namespace {
using ptu::kSectors;
using ptu::wrap_sector;

// A wall sector: its axis and reading.
struct WallSample {
  double axis_deg = 0.0;  // sector axis, degrees (unwrapped near the passage)
  double range = 0.0;     // reading from the face, mm
};

// Why walk outwards from each edge: the sectors next to the edge see the edge itself (equal
// ranges), the following ones the wall beside the passage, until a jump or no echo.
int collect_wall(const PanTiltScan& scan, int edge, int dir, double edge_axis, const DoorSettings& s,
                 std::array<WallSample, 32>& out, int n) {
  const auto& r = scan.raw;
  const std::int32_t edge_r = r[static_cast<std::size_t>(edge)];
  int k = edge;
  double axis = edge_axis;
  bool past_edge = false;
  int taken = 0;
  for (int step = 0; step < 18 && taken < s.max_wall_sectors && n < static_cast<int>(out.size()); ++step) {
    const int next = wrap_sector(k + dir);
    const std::int32_t rk = r[static_cast<std::size_t>(k)], rn = r[static_cast<std::size_t>(next)];
    if (rn <= 0 || rn >= s.max_mm || std::abs(rn - rk) > s.corners.margin_mm) break;
    k = next;
    axis += dir * ptu::kSectorDegrees;
    // Where this reading really looked (the firing is within a degree of the sector's angle).
    const double nominal = ptu::kSectorDegrees * k;
    const double actual = axis + ptu::wrap_deg(scan.direction[static_cast<std::size_t>(k)] * 0.01 - nominal - (axis - nominal));
    if (!past_edge && std::abs(rn - edge_r) <= s.geometry.same_echo_mm) continue;  // still the edge
    past_edge = true;
    out[static_cast<std::size_t>(n++)] = WallSample{actual, static_cast<double>(rn)};
    ++taken;
  }
  return n;
}

// Why walk: the sector next to the gap may hear the edge's far corner (the wall's thickness)
// while the next ones hear its near corner, nearer; the edge is the near one.
int nearest_edge(const PanTiltScan& scan, int edge, int dir, const DoorSettings& s) {
  const auto& r = scan.raw;
  for (int step = 0; step < 3; ++step) {
    const int next = wrap_sector(edge + dir);
    const std::int32_t re = r[static_cast<std::size_t>(edge)], rn = r[static_cast<std::size_t>(next)];
    if (rn <= 0 || rn >= re - s.geometry.same_echo_mm || re - rn > s.corners.margin_mm) break;
    edge = next;
  }
  return edge;
}

// Signed angle difference a − b wrapped into (−180, 180], degrees.
double diff_deg(double a, double b) { return ptu::wrap_deg(a - b); }
}  // namespace

DoorEstimate estimate_door(const PanTiltScan& scan, const ptu::Echoes& echoes, const DoorSettings& s) {
  DoorEstimate d;
  d.lock = find_corners(scan.differences, scan.filtered, s.corners);
  const CornerLock& c = d.lock;
  if (!c.locked || c.right_value >= s.max_mm || c.left_value >= s.max_mm) return d;
  const ptu::EchoGeometry& g = s.geometry;
  const int right = nearest_edge(scan, c.right, -1, s), left = nearest_edge(scan, c.left, +1, s);
  const ptu::Echo& er = echoes[static_cast<std::size_t>(right)];
  const ptu::Echo& el = echoes[static_cast<std::size_t>(left)];
  if (!er.valid || !el.valid || er.far || el.far) return d;

  // Edge points relative to the pan axis, and the axes of the edge sectors unwrapped around them.
  const double rx = er.x_mm - g.pivot_x_mm, ry = er.y_mm, lx = el.x_mm - g.pivot_x_mm, ly = el.y_mm;
  const double right_axis = ptu::kSectorDegrees * c.right - ptu::kSectorDegrees * ptu::wrap_sector(c.right - right);
  const double left_axis = ptu::kSectorDegrees * c.right + ptu::kSectorDegrees * (c.gap_sectors + 1) +
                           ptu::kSectorDegrees * ptu::wrap_sector(left - c.left);
  std::array<WallSample, 32> wall{};
  int n = collect_wall(scan, right, -1, right_axis, s, wall, 0);
  n = collect_wall(scan, left, +1, left_axis, s, wall, n);
  d.wall_sectors = n;

  // The normal: the passage's direction ± search_deg; D for a trial normal is the mean of what
  // every sample implies, and the best normal leaves the least spread.
  const double guess = std::atan2(0.5 * (ry + ly), 0.5 * (rx + lx)) / robot::kDeg;
  const double h = g.beam_half_deg;
  double best_sse = 1e300, best_psi = guess, best_D = 0.0;
  const int steps = static_cast<int>(std::lround(2.0 * s.search_deg / s.step_deg));
  std::array<double, 34> implied{};
  for (int i = 0; i <= steps; ++i) {
    const double psi = guess - s.search_deg + i * s.step_deg;
    const double cp = std::cos(psi * robot::kDeg), sp = std::sin(psi * robot::kDeg);
    int m = 0;
    for (int j = 0; j < n; ++j) {
      const WallSample& w = wall[static_cast<std::size_t>(j)];
      const double off = std::abs(diff_deg(w.axis_deg, psi));
      const double e = std::max(0.0, off - h);
      implied[static_cast<std::size_t>(m++)] = w.range * std::cos(e * robot::kDeg) + g.face_mm * std::cos(off * robot::kDeg);
    }
    implied[static_cast<std::size_t>(m++)] = rx * cp + ry * sp;  // the edges lie on the wall line
    implied[static_cast<std::size_t>(m++)] = lx * cp + ly * sp;
    double mean = 0.0;
    for (int j = 0; j < m; ++j) mean += implied[static_cast<std::size_t>(j)];
    mean /= m;
    double sse = 0.0;
    for (int j = 0; j < m; ++j) sse += (implied[static_cast<std::size_t>(j)] - mean) * (implied[static_cast<std::size_t>(j)] - mean);
    if (sse < best_sse) {
      best_sse = sse;
      best_psi = psi;
      best_D = mean;
    }
  }
  if (best_D <= 0.0) return d;
  const double nx = std::cos(best_psi * robot::kDeg), ny = std::sin(best_psi * robot::kDeg);  // unit normal
  const double tx = -ny, ty = nx;                                                // along the wall, to the left

  // Each edge on the line: where its localised echo falls, and where its range from its face
  // says, weighted by how well each is known there (a range says little near the foot of the
  // perpendicular, where along-the-wall distance hardly changes it; a bearing is ±2.5°).
  auto place = [&](const ptu::Echo& e, int sector, double& px, double& py) {
    const double axis = ptu::kSectorDegrees * sector * robot::kDeg;
    const double fx = g.face_mm * std::cos(axis), fy = g.face_mm * std::sin(axis);
    const double to_line = best_D - (fx * nx + fy * ny);
    const double qx = fx + to_line * nx, qy = fy + to_line * ny;  // foot of the face on the line
    const double ex = e.x_mm - g.pivot_x_mm, ey = e.y_mm;
    const double along_echo = (ex - qx) * tx + (ey - qy) * ty;
    const double r = scan.raw[static_cast<std::size_t>(sector)];
    double along = along_echo;
    if (r * r > to_line * to_line) {
      const double along_range = std::copysign(std::sqrt(r * r - to_line * to_line), along_echo);
      const double var_range = std::pow(s.range_sigma_mm * r / std::max(std::abs(along_range), 1.0), 2.0);
      const double var_echo = std::pow(r * s.bearing_sigma_deg * robot::kDeg, 2.0);
      along = (along_range * var_echo + along_echo * var_range) / (var_echo + var_range);
    }
    px = qx + along * tx;
    py = qy + along * ty;
  };
  double Rx = 0, Ry = 0, Lx = 0, Ly = 0;
  place(er, right, Rx, Ry);
  place(el, left, Lx, Ly);
  d.ok = true;
  d.normal_deg = ptu::wrap_deg(best_psi);
  d.right_x = Rx + g.pivot_x_mm;
  d.right_y = Ry;
  d.left_x = Lx + g.pivot_x_mm;
  d.left_y = Ly;
  d.center_x = 0.5 * (d.right_x + d.left_x);
  d.center_y = 0.5 * (d.right_y + d.left_y);
  d.width_mm = std::hypot(Lx - Rx, Ly - Ry);
  d.wall_rms_mm = std::sqrt(best_sse / (n + 2));
  return d;
}

}  // namespace robuter::gate
