// SPDX-License-Identifier: GPL-3.0-or-later
// What the ring could not see from the pose the robot last started from: where a creep may go.
#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "modules/emergency/body_box.hpp"
#include "modules/emergency/pose_history.hpp"

namespace robuter::emergency {

// The body (its near field: the blanking range) and the ring the blind set is built from.
struct StartBlindSettings : BodyBox {
  double wedge_reach = 0.65;  // gaps between the cones count as blind this far from the body (where
                              // the front cones' wedges close), m
  double travel = 0.65;       // the start pose is dropped once the axle is this far from it, m
  double edge = 0.036;        // a cone's certificates cover whole cells: its edges and its blanking
                              // arc count as blind this much into it (a cell's diagonal), m
  std::uint32_t scans = 2;    // full ring passes at rest before a start pose is taken, count
};

// A creep through space no reading has certified is safe only where no reading *could* have
// looked: the blind near field (inside the blanking range) and the gaps between the cones, as
// seen from a pose where the robot stood still while the ring made full passes. Cells the ring
// could see from there carry a certificate or evidence; a robot that moved into unseen space
// ahead of its ring — a slow `UD`, a short listening window — is not creeping from a start, and
// is held instead (docs/SAFETY.md §13). The set is taken once the robot has been at rest for
// `scans` full passes, kept while it moves — up to `travel` from it: a start is a start, not a
// licence to creep through the gaps of a pose left behind (the random sequences found a curve
// that crept 0.7 m along a box standing in a side gap of the start pose) — and dropped when it
// comes to rest again.
class StartBlind {
 public:
  explicit StartBlind(const StartBlindSettings& s) : s_(s) {}
  // One activation: the robot's pose now, whether it is at rest, the ring's pass count and the
  // read tick of each of `sensors` sensors (those that read at rest are the cones that count).
  void observe(std::uint64_t tick, const Pose2& now, bool at_rest, std::uint32_t scans,
               const std::uint64_t* read_tick, int sensors);
  // Forgets the start (a new odometry frame).
  void reset();
  // Whether the point p (odometry frame, m) was blind from the start pose; false without one.
  bool covers(const Eigen::Vector2d& p) const;
  bool valid() const { return valid_; }

 private:
  StartBlindSettings s_;
  bool resting_ = false;          // the robot was at rest at the last activation
  std::uint64_t rest_tick_ = 0;   // tick the rest began
  std::uint32_t rest_scans_ = 0;  // the ring's pass count when it began
  bool valid_ = false;            // a start pose is held
  Pose2 start_;                   // the start pose, odometry frame
  std::uint32_t fired_ = 0;       // bit s-1: sensor s read during the rest
};

}  // namespace robuter::emergency
