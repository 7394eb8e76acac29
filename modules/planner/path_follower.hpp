// SPDX-License-Identifier: GPL-3.0-or-later
// Follows legs (turn in place, then drive straight, forward or backing) with wheel-speed requests. Pure.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "modules/planner/route.hpp"

namespace robuter::planner {

// Gains, tolerances and limits of the follower.
struct FollowerSettings {
  double position_tolerance = 0.02;  // m: a leg ends this close to (or past) its end
  double angle_tolerance = 0.035;    // rad (2°): turned far enough
  double reorient_angle = 0.35;      // rad (20°): heading error while driving that stops to turn again
  std::int32_t max_drive_cm_s = 20;  // cm/s, fastest wheel while driving
  std::int32_t max_turn_cm_s = 10;   // cm/s, fastest wheel while turning in place
  std::int32_t min_cm_s = 1;         // cm/s, slowest non-zero wheel speed
  double drive_gain = 1.0;           // 1/s: speed (cm/s) per cm left
  double turn_gain = 1.5;            // 1/s: turning rate per rad of error
  double heading_gain = 1.0;         // 1/s: steering rate per rad of heading error while driving
  std::uint32_t wheel_base_mm = 600; // mm, DBW
};

// Wheel speeds asked by the follower, cm/s.
struct Wheels {
  std::int32_t left = 0;   // cm/s
  std::int32_t right = 0;  // cm/s
};

class PathFollower {
 public:
  static constexpr std::size_t kMaxLegs = 64;  // legs of one prefix

  explicit PathFollower(const FollowerSettings& s = {}) : s_(s) {}
  // Why: a new prefix to execute (copied: the planner's buffers change at the next plan).
  void start(std::span<const Leg> legs);
  // Why: stop following (the caller asks the gate for zero speeds).
  void cancel() { count_ = index_ = 0; }
  // Why: one control step from the pose (m; heading unwrapped, rad): the speeds to ask for;
  // zero once the last leg is done.
  Wheels step(const plan::Pose2& now);
  bool active() const { return index_ < count_; }
  // True while the current leg is still turning in place (not yet driving).
  bool turning() const { return active() && !driving_; }
  std::size_t leg_index() const { return index_; }
  const Leg* current() const { return active() ? &legs_[index_] : nullptr; }
  const FollowerSettings& settings() const { return s_; }

 private:
  // Speeds turning on the spot to reduce `error` (rad, positive = counter-clockwise).
  Wheels turn(double error) const;

  FollowerSettings s_;
  std::array<Leg, kMaxLegs> legs_{};
  std::size_t count_ = 0;   // legs held
  std::size_t index_ = 0;   // leg being executed
  bool driving_ = false;    // the current leg's turn is done
};

}  // namespace robuter::planner
