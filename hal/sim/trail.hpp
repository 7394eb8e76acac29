// SPDX-License-Identifier: GPL-3.0-or-later
// A fixed-capacity record of where the robot has been, for pictures (oldest points drop off).
#pragma once

#include <cstddef>
#include <vector>

#include "hal/sim/types.hpp"

namespace robuter::sim {

// Ring buffer of positions; allocates only at construction.
class Trail {
 public:
  explicit Trail(std::size_t capacity = 4096) : points_(capacity > 0 ? capacity : 1) {}

  // Appends a point, overwriting the oldest when full.
  void push(const Vec2& p) {
    points_[(first_ + size_) % points_.size()] = p;
    if (size_ < points_.size()) {
      ++size_;
    } else {
      first_ = (first_ + 1) % points_.size();
    }
  }

  // Forgets every point.
  void clear() { first_ = size_ = 0; }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

  // The i-th point, oldest first.
  const Vec2& operator[](std::size_t i) const { return points_[(first_ + i) % points_.size()]; }

 private:
  std::vector<Vec2> points_;  // storage, m
  std::size_t first_ = 0;     // index of the oldest point
  std::size_t size_ = 0;      // points stored
};

}  // namespace robuter::sim
