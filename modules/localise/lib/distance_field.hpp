// SPDX-License-Identifier: GPL-3.0-or-later
// The likelihood field's base: each cell's distance to the nearest occupied cell of a given map.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace robuter::loc {

// Size and placement of a grid in the world.
struct FieldGeometry {
  int width = 0;                                    // cells along x
  int height = 0;                                   // cells along y
  double resolution = 0.05;                         // m per cell side
  Eigen::Vector2d origin = Eigen::Vector2d::Zero(); // world position of cell (0, 0)'s lower-left corner, m
};

// Exact Euclidean distance (Felzenszwalb and Huttenlocher's two-pass transform) from every cell
// centre to the nearest occupied cell centre, capped at `max_distance`. Built once, at start-up
// (it allocates); every query after that is a table read.
class DistanceField {
 public:
  DistanceField() = default;
  // `occupied` holds width × height cells, row by row from y = 0; non-zero = occupied.
  DistanceField(const FieldGeometry& geometry, std::span<const std::uint8_t> occupied,
                double max_distance);

  const FieldGeometry& geometry() const { return geo_; }
  double max_distance() const { return max_distance_; }
  bool empty() const { return dist_.empty(); }

  // Whether world point p lies on the grid.
  bool contains(const Eigen::Vector2d& p) const {
    const double fx = (p.x() - geo_.origin.x()) / geo_.resolution;
    const double fy = (p.y() - geo_.origin.y()) / geo_.resolution;
    return fx >= 0.0 && fy >= 0.0 && fx < geo_.width && fy < geo_.height;
  }
  // Distance at the cell holding world point p, m; max_distance() outside the grid.
  double at(const Eigen::Vector2d& p) const {
    const std::size_t i = index(p);
    return i == kOutside ? max_distance_ : dist_[i];
  }
  // The unit normal of the nearest wall at the cell holding p (the field's gradient there,
  // central differences a cell either side: pointing away from the wall), into `out`; false
  // where the field is flat there (outside the grid, no wall within reach, a ridge between two).
  bool normal(const Eigen::Vector2d& p, Eigen::Vector2d& out) const {
    const std::size_t i = index(p);
    if (i == kOutside || normal_[i] == kNoNormal) return false;
    out = directions_[normal_[i]];
    return true;
  }
  // Distance of cell (x, y), m (inside the grid only).
  double cell(int x, int y) const {
    return dist_[static_cast<std::size_t>(y) * static_cast<std::size_t>(geo_.width) + static_cast<std::size_t>(x)];
  }
  // World position of a cell's centre, m.
  Eigen::Vector2d center(int x, int y) const {
    return geo_.origin + geo_.resolution * Eigen::Vector2d(x + 0.5, y + 0.5);
  }

 private:
  static constexpr std::size_t kOutside = static_cast<std::size_t>(-1);
  static constexpr std::uint8_t kNoNormal = 255;  // normal_'s "flat"; 0..254 are directions
  // The cell holding p, row by row; kOutside off the grid.
  std::size_t index(const Eigen::Vector2d& p) const {
    const double fx = (p.x() - geo_.origin.x()) * inv_resolution_;
    const double fy = (p.y() - geo_.origin.y()) * inv_resolution_;
    if (!(fx >= 0.0 && fy >= 0.0 && fx < geo_.width && fy < geo_.height)) return kOutside;
    return static_cast<std::size_t>(static_cast<int>(fy)) * static_cast<std::size_t>(geo_.width) +
           static_cast<std::size_t>(static_cast<int>(fx));
  }

  FieldGeometry geo_;
  double max_distance_ = 0.0;  // cap of every distance, m
  double inv_resolution_ = 0.0;  // cells per m
  std::vector<float> dist_;    // per cell, m
  std::vector<std::uint8_t> normal_;  // per cell: the gradient's direction, 255 steps of the turn
  std::array<Eigen::Vector2d, kNoNormal> directions_{};  // unit vector of each step
};

}  // namespace robuter::loc
