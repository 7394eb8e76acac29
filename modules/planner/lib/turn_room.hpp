// SPDX-License-Identifier: GPL-3.0-or-later
// The room a turn in place leaves, measured from the robot's own pose against the map's obstacles.
#pragma once

#include <array>

#include "modules/planner/lib/footprint.hpp"
#include "modules/planner/lib/geometry.hpp"
#include "modules/planner/lib/occupancy_map.hpp"

namespace robuter::plan {

// Why: the turn layers are cells and square-grown bodies, made for the search: they forbid a
// turn up to a cell and a grown corner (about 10 cm for a 25 cm clearance) early, so no turn at
// all is allowed in a 2.10 m corridor where the body's corners pass 0.27 m from the walls. A
// turn where the robot stands is measured from its pose instead, against the body grown by the
// clearance with rounded corners (every point within `clearance` of the body).
//
// The grown body seen from the axle: its radius per direction (the body frame, 0.25 degree
// bins, each bin's value the largest radius over the bin). An obstacle point at radius rho and
// bearing phi from the axle is too close at heading theta when the grown body's radius toward
// phi - theta exceeds rho; a cell is checked with its nearest radius and the bearings its square
// spans, so the answer errs only on the side of refusing.
class TurnEnvelope {
 public:
  static constexpr int kBins = 1440;  // 0.25 degree each
  static constexpr int kBlock = 32;   // bins per block of the second level (1440 = 45 x 32)

  TurnEnvelope(const RectangleFootprint& body, double clearance);

  // Why: true when, at every heading from pose.heading to target (rad, either way round, any
  // span), no occupied cell of the map comes within the clearance of the body at `pose` (the
  // axle). Unknown cells count as free, as in the layers. No allocation; work bounded by the
  // cells within reach() of the axle times the bins the turn spans.
  bool turn_is_clear(const OccupancyMap& map, const Pose2& pose, double target) const;

  // Why: tests: the grown body's radius toward `angle` (rad, body frame), exact.
  double radius(double angle) const;
  // Why: tests and culling: the grown body's farthest point from the axle (m).
  double reach() const { return reach_; }

 private:
  RectangleFootprint body_;
  double clearance_;                     // m, kept all round the body
  double reach_;                         // m, farthest point of the grown body from the axle
  std::array<double, kBins> bin_max_{};  // m, per bearing bin: the largest radius over the bin
  std::array<double, kBins / kBlock> block_max_{};  // m, per block of kBlock bins: their largest

  // Why: the largest radius over `count` bins from `first` (wrapping round), whole blocks at once.
  double max_over(int first, int count) const;
};

// Why: tests: the least distance (m) between the body at `pose` and the square of `cell` (0 when
// they overlap), exact.
double body_cell_distance(const OccupancyMap& map, const RectangleFootprint& body, const Pose2& pose, Cell cell);

}  // namespace robuter::plan
