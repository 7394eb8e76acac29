// SPDX-License-Identifier: GPL-3.0-or-later
// The body's rectangle swept along the arc of wheel speeds over the stopping horizon, judged on the grid.
#pragma once

#include <cstdint>
#include <vector>

#include "modules/emergency/body_box.hpp"
#include "modules/emergency/evidence_grid.hpp"
#include "modules/emergency/pose_history.hpp"
#include "modules/emergency/start_blind.hpp"

namespace robuter::emergency {

// The robot (its body, and the blind near field around it: the blanking range) and the stopping
// model the envelope is built from.
struct EnvelopeSettings : BodyBox {
  double margin = 0.030;         // clearance kept around the body, m
  double wheel_base = 0.600;     // between the drive wheels, m
  double decel = 1.0;            // braking deceleration of each wheel, m/s²
  double reversal_decel = 0.5;   // a wheel told to reverse slows at the acceleration limit only, m/s²
  double reaction = 0.11;        // from one decision to the next reaching the drive, s
  double creep = 0.05;           // fastest wheel allowed where only the blind near field is unknown, m/s
  double step = 0.025;           // spacing of outline samples and of poses along the arc, m
  std::uint64_t free_age_ticks = 300;  // free certificates older than this do not count, ticks
  std::uint64_t near_age_ticks = 1200; // in the blind near field, which no reading can refresh, this long, ticks
};

// The envelope's verdict on one request.
struct EnvelopeVerdict {
  double fraction = 1.0;   // largest share k ∈ [0, 1] of the request whose envelope is clear
  bool obstacle = false;   // k = 0 because obstacle evidence lies in the creep envelope (protective stop)
  bool missing = false;    // the request's own envelope reaches free space not certified recently
  int poses = 0;           // poses examined (work done), count
  Eigen::Vector2d where = Eigen::Vector2d::Zero();  // outline point (robot frame, m) that met the first limit
};

// Tests a request (left, right wheel speeds) against the evidence grid: the rectangle grown by the
// margin, at poses along the request's arc from now over the horizon k·t_r + k²·w/(2a) (equivalent
// time at the full request: t_r of reaction then braking at `decel` from the fastest wheel w),
// must meet only cells certified free within the age limit, or cells under the body now. Cells of
// the blind near field (within `near` of the body) that are not certified allow a creep speed.
// Only the leading part of the outline is sampled (points whose velocity leaves the body): the
// region a motion sweeps is what that part crosses. Work per request: ≤ kMaxPoses poses × the
// leading outline points (≤ 2 × perimeter / step per offset).
class SweptEnvelope {
 public:
  static constexpr int kMaxPoses = 160;  // poses along one arc at most (the step grows past it)
  static constexpr int kRefine = 4;      // bisection steps between the last clear and first blocked pose

  // Precomputes the outline samples (the only allocation).
  explicit SweptEnvelope(const EnvelopeSettings& s);
  // The largest clear fraction of (left, right) m/s for a robot at `now` at `tick`. A creep goes
  // only through space `blind` says no reading could have looked at from the start pose (null: no
  // creep); `ring_alive` false (the ring has read nothing within the age limit): the near field's
  // certificates get no longer life and no creep is allowed; `bumpers` false (masked off): no
  // creep either.
  EnvelopeVerdict judge(const EvidenceGrid& g, const Pose2& now, double left, double right, std::uint64_t tick,
                        const StartBlind* blind, bool ring_alive = true, bool bumpers = true) const;
  // Whether braking now from the motion (v m/s, w rad/s) at `decel` m/s² sweeps obstacle evidence.
  bool braking_meets_obstacle(const EvidenceGrid& g, const Pose2& now, double v, double w, double decel,
                              std::uint64_t tick) const;
  // The equivalent time of the horizon for a fraction k of a request whose fastest wheel is w m/s, s.
  double horizon(double k, double w, double decel) const;
  // Its inverse: the largest k whose horizon is at most tau.
  double fraction_for(double tau, double w, double decel) const;
  const EnvelopeSettings& settings() const { return s_; }
  void set_ages(std::uint64_t free_ticks, std::uint64_t near_ticks) {
    s_.free_age_ticks = free_ticks;
    s_.near_age_ticks = near_ticks;
  }
  std::size_t outline_points() const { return outline_.size(); }

 private:
  // A sample of the grown outline, robot frame.
  struct OutlinePoint {
    Eigen::Vector2d q;  // position, m
    Eigen::Vector2d n;  // outward normal of its face
  };
  // What one pose meets, worst first: `near_unknown` is space not certified that no reading could
  // have looked at from the start pose (StartBlind), where a creep may go.
  enum class Meets : std::uint8_t { clear, near_unknown, missing, obstacle };
  // How the grid is read for one request.
  struct Look {
    std::uint64_t tick = 0;             // now, ticks
    std::uint64_t near_age = 0;         // how old a certificate of the blind near field may be, ticks
    const StartBlind* blind = nullptr;  // where a creep may go (null: nowhere)
  };
  // The worst the leading outline meets at the pose `tau` along the arc of (v, w) from `now`.
  Meets meets(const EvidenceGrid& g, const Pose2& now, double v, double w, double tau, const Look& look,
              Eigen::Vector2d* where = nullptr) const;
  // Scans the arc from 0 to tau_max; returns the (refined) first tau at which the pose meets at
  // least `level`, or a value above tau_max when none; `what` gets what it met there.
  double first(const EvidenceGrid& g, const Pose2& now, double v, double w, double tau_max, Meets level,
               const Look& look, Meets& what, int& poses, Eigen::Vector2d* where = nullptr) const;

  EnvelopeSettings s_;
  std::vector<OutlinePoint> outline_;  // faces of the rectangles grown by 0, step, …, margin
  double reach_ = 1.0;                 // farthest outline point from the axle midpoint, m
};

}  // namespace robuter::emergency
