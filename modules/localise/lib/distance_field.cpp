// SPDX-License-Identifier: GPL-3.0-or-later
// The two-pass exact Euclidean distance transform behind DistanceField.
#include "modules/localise/lib/distance_field.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace robuter::loc {
namespace {

constexpr double kFar = 1e20;  // squared distance of a cell with nothing occupied in its line

// One line of the transform: d[q] = min over p of (q - p)² + f[p], by the lower envelope of
// parabolas (v: their apexes, z: where each takes over).
void transform_line(const double* f, int n, double* d, int* v, double* z) {
  int k = 0;
  v[0] = 0;
  z[0] = -kFar;
  z[1] = kFar;
  const auto meet = [&](int q, int p) {  // where the parabola at q takes over from the one at p
    return ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * (q - p));
  };
  for (int q = 1; q < n; ++q) {
    double s = meet(q, v[k]);
    while (s <= z[k]) s = meet(q, v[--k]);  // z[0] = -kFar: never passes k = 0
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = kFar;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    const double dq = q - v[k];
    d[q] = dq * dq + f[v[k]];
  }
}

}  // namespace

DistanceField::DistanceField(const FieldGeometry& geometry, std::span<const std::uint8_t> occupied,
                             double max_distance)
    : geo_(geometry), max_distance_(max_distance), inv_resolution_(1.0 / geometry.resolution) {
  const int w = geo_.width, h = geo_.height;
  if (w <= 0 || h <= 0 || occupied.size() != static_cast<std::size_t>(w) * static_cast<std::size_t>(h)) return;
  const auto cells = occupied.size();
  std::vector<double> sq(cells);
  for (std::size_t i = 0; i < cells; ++i) sq[i] = occupied[i] ? 0.0 : kFar;
  const int n = std::max(w, h);
  std::vector<double> f(static_cast<std::size_t>(n)), d(static_cast<std::size_t>(n)), z(static_cast<std::size_t>(n) + 1);
  std::vector<int> v(static_cast<std::size_t>(n));
  const auto at = [w](int x, int y) { return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x); };
  for (int x = 0; x < w; ++x) {  // columns
    for (int y = 0; y < h; ++y) f[static_cast<std::size_t>(y)] = sq[at(x, y)];
    transform_line(f.data(), h, d.data(), v.data(), z.data());
    for (int y = 0; y < h; ++y) sq[at(x, y)] = d[static_cast<std::size_t>(y)];
  }
  for (int y = 0; y < h; ++y) {  // rows
    for (int x = 0; x < w; ++x) f[static_cast<std::size_t>(x)] = sq[at(x, y)];
    transform_line(f.data(), w, d.data(), v.data(), z.data());
    for (int x = 0; x < w; ++x) sq[at(x, y)] = d[static_cast<std::size_t>(x)];
  }
  dist_.resize(cells);
  for (std::size_t i = 0; i < cells; ++i)
    dist_[i] = static_cast<float>(std::min(max_distance_, std::sqrt(sq[i]) * geo_.resolution));
  // Each cell's gradient direction, quantised (1.4°): the sonar model asks it in its inner loops.
  for (int k = 0; k < kNoNormal; ++k) {
    const double a = 2.0 * std::numbers::pi * k / kNoNormal;
    directions_[static_cast<std::size_t>(k)] = Eigen::Vector2d(std::cos(a), std::sin(a));
  }
  const auto dist = [&](int x, int y) {
    return (x < 0 || y < 0 || x >= w || y >= h) ? max_distance_ : static_cast<double>(dist_[at(x, y)]);
  };
  normal_.assign(cells, kNoNormal);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double gx = dist(x + 1, y) - dist(x - 1, y), gy = dist(x, y + 1) - dist(x, y - 1);
      if (std::hypot(gx, gy) <= 0.5 * geo_.resolution) continue;  // flat: no wall near, or a ridge
      double a = std::atan2(gy, gx) / (2.0 * std::numbers::pi);
      if (a < 0.0) a += 1.0;
      normal_[at(x, y)] = static_cast<std::uint8_t>(static_cast<int>(std::lround(a * kNoNormal)) % kNoNormal);
    }
}

}  // namespace robuter::loc
