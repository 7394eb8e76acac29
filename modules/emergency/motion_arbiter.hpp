// SPDX-License-Identifier: GPL-3.0-or-later
// The motion arbiter: the one place that decides who drives — the operator or one automatic mode.
#pragma once

#include <cstdint>
#include <span>

#include "modules/topics.hpp"

namespace robuter::emergency {

// One row of the arbitration table (docs/SAFETY.md §1 states the same table).
struct ArbitrationRule {
  OperatorAction action;   // the operator's command
  MotionSource takes;      // who drives after it (link, go_to: the operator)
  bool starts;             // it hands the robot to `takes` for a new run
  MotionSource own_stop;   // the automatic mode this command is the stop of (link: none)
};

// The table: every operator action pre-empts and ends a running automatic mode at once, which
// reports `operator` — or `cancelled` when the action is that mode's own stop command.
std::span<const ArbitrationRule> arbitration_table();

// Whether a source is an automatic mode (gate, doors, planner, demo) rather than the operator.
constexpr bool automatic(MotionSource s) {
  return s == MotionSource::gate || s == MotionSource::doors || s == MotionSource::planner || s == MotionSource::demo;
}

// Keeps who drives. Pure, no heap; the emergency module feeds it and publishes authority().
class MotionArbiter {
 public:
  // Applies one operator action (table above).
  void take(OperatorAction a);
  // More operator actions arrived than could be kept: the worst case, an operator's motion.
  void lost_actions() { take(OperatorAction::motion); }
  // An emergency tripped (stop byte, bumper, link loss, drive fault, obstacle under the seed's
  // rule…): the automatic mode ends (`emergency`); nothing of it resumes after XR.
  void emergency_stop();
  // A protective stop began (an obstacle in the envelope, no latch): the operator's motion is
  // forgotten — the go-to ends (`protective`) — while an automatic mode keeps the robot and
  // goes on once the envelope is clear (docs/SAFETY.md §13).
  void protective_stop();
  // The passage finder is aligned and hands the robot to the door crossing ([gate] hand_over).
  void hand_over_to_doors();
  // The planner, at the point before a narrow door of an XQ route, lends the robot to the door
  // crossing ([places] cross_doors): a new run of the crossing; the planner's run goes on,
  // waiting. Whatever ends the crossing's run early (the operator, Af, XH, an emergency) ends the
  // planner's too; the crossing ending by itself (crossed, or failed) gives the robot back.
  void lend_to_doors();
  // The lent crossing ended by itself: the robot is the lender's again, in the same run.
  void give_back();
  // A mode started at boot by configuration ([demo] enabled).
  void start_at_boot(MotionSource s);
  // May requests from `s` reach the gate now: only the owner's do.
  bool accepts(MotionSource s) const { return s == a_.owner; }
  const MotionAuthority& authority() const { return a_; }

 private:
  // The running automatic mode (if any) ends with `why`.
  void end_running(ModeReason why);
  // `s` drives from now, in a new run.
  void hand_to(MotionSource s);

  MotionAuthority a_{};  // the decision (detections and tick are the module's)
};

}  // namespace robuter::emergency
