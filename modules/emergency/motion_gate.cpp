// SPDX-License-Identifier: GPL-3.0-or-later
// The gate's decision: re-enable, requests, detections, then trip / latch / hold / grant.
#include "modules/emergency/motion_gate.hpp"

#include <algorithm>
#include <cmath>

#include "modules/emergency/obstacle_check.hpp"

namespace robuter::emergency {

// A wheel speed scaled by the envelope's fraction, truncated towards zero (never above the share).
std::int32_t scaled(std::int32_t speed, double fraction) {
  if (fraction >= 1.0) return speed;
  return static_cast<std::int32_t>(std::trunc(static_cast<double>(speed) * std::max(fraction, 0.0)));
}

// Forgetting is how the seed's "rtm = FALSE" is made final: an old speed can never come back.
void MotionGate::forget() {
  has_request_ = false;
  left_ = right_ = 0;
  holding_ = false;
  automatic_ = false;
  clear_timing_ = false;
}

// Order matters: a re-enable is judged on the conditions present now; requests are taken before
// the detections so a request that meets an emergency is forgotten in the same activation;
// every detection runs every activation (the seed skipped the bumper and link checks while it
// waited for sonar data).
GateDecision MotionGate::step(const GateInputs& in) {
  GateDecision d;
  const std::uint64_t tick = in.tick;
  const bool bumper_now = (s_.enabled & kDetectBumper) && in.bumpers != 0;
  const bool comm_now = (s_.enabled & kDetectComm) && tick > in.last_message_tick &&
                        tick - in.last_message_tick > s_.comm_limit_ticks;
  // A trip's cause is not gone while the robot it stopped is still braking: nothing is
  // re-enabled and nothing moves before it is at rest (docs/SAFETY.md §4).
  if (stopping_ && in.at_rest) {
    stopping_ = false;
    stopping_cause_ = EmergencyCause::none;
  }
  const bool condition_now = bumper_now || comm_now || in.drive_fault || stopping_;

  // 1. Re-enable: only when no condition is present; the request is forgotten either way.
  if (in.reenable && latched_ && !condition_now) {
    latched_ = false;
    latched_cause_ = EmergencyCause::none;
    forget();
    d.cleared = true;
  }
  // 2. Requests. Any servo request stops the motion (ASF stops; ASN must not move anything).
  if (in.servo_request) forget();
  if (in.new_request && !latched_) {
    has_request_ = true;
    left_ = in.left;
    right_ = in.right;
    source_ = in.source;
    request_tick_ = tick;
    holding_ = false;
    automatic_ = in.automatic;
    // An operator's new request is judged afresh; an automatic mode's waits out the clear time.
    if (!in.automatic) {
      protective_ = false;
      clear_timing_ = false;
    }
  }

  // 3. Detections.
  const bool moving = has_request_ && (left_ != 0 || right_ != 0);
  EmergencyCause cause = EmergencyCause::none;
  if (in.stop_byte) cause = EmergencyCause::stop_byte;
  else if (in.drive_fault) cause = in.drive_cause != EmergencyCause::none ? in.drive_cause : EmergencyCause::drive_fault;
  else if (bumper_now) cause = EmergencyCause::bumper;
  else if (comm_now) cause = EmergencyCause::comm_loss;
  else if (moving && s_.motion_timeout_ticks > 0 && tick - request_tick_ > s_.motion_timeout_ticks)
    cause = EmergencyCause::motion_timeout;
  else if (stopping_) cause = stopping_cause_;

  const int main = moving ? main_sensor(left_, right_, s_.wheel_base_mm) : 0;
  const std::uint32_t safety = moving ? safety_distance_mm(left_, right_, s_.min_safety_mm, s_.safety_mm_per_cm_s) : 0;
  d.state.main_sensor = main;
  d.state.watch = watch_mask(main);
  d.state.safety_mm = safety;
  bool held = false;
  const bool use_envelope = s_.envelope && in.envelope != nullptr;
  bool protective_now = false;  // obstacle evidence stops even a creep
  double fraction = 1.0;        // share of the request the envelope grants
  if (cause == EmergencyCause::none && moving && (s_.enabled & kDetectUltrasonic)) {
    if (use_envelope) {
      const EnvelopeVerdict v = in.envelope->judge(left_, right_, (s_.enabled & kDetectBumper) != 0);
      fraction = v.fraction;
      const bool nothing = scaled(left_, fraction) == 0 && scaled(right_, fraction) == 0;
      protective_now = v.obstacle || (nothing && !v.missing);
      held = nothing && !protective_now;
    } else if (in.ranges != nullptr) {
      const WatchVerdict v = check_watch(watch_sensors(main), *in.ranges, safety, tick, s_.stale_ticks);
      if (v.result == WatchResult::obstacle) cause = EmergencyCause::obstacle;
      held = v.result == WatchResult::hold;
      d.state.sensor = v.sensor;
    }
  }
  // A paused automatic request waits until its envelope has been clear for the clear time; new
  // evidence starts the clock over.
  const bool evidence = protective_now;
  if (evidence) clear_timing_ = false;
  if (protective_ && !protective_now && has_request_ && automatic_ && cause == EmergencyCause::none && !latched_) {
    if (held || !moving) {
      clear_timing_ = false;
    } else if (!clear_timing_) {
      clear_timing_ = true;
      clear_since_ = tick;
    }
    const bool waited = clear_timing_ && tick - clear_since_ >= s_.protective_clear_ticks;
    if (waited) {
      protective_ = false;
      clear_timing_ = false;
      d.resumed = true;
    } else if (moving && !held) {
      protective_now = true;  // still paused: nothing granted yet
    }
  }

  // 4. Verdict.
  if (cause != EmergencyCause::none) {
    // A trip is a condition that interrupts something (a motion, a powered servo) or the
    // operator's stop byte; a condition met at rest only inhibits until it goes.
    const bool interrupts = moving || in.servo_on || in.stop_byte;
    if (interrupts) {
      ++trips_;
      d.tripped = true;
      if (s_.latch && !latched_) {
        latched_ = true;
        latched_cause_ = cause;
      }
      if (moving || !in.at_rest) {
        stopping_ = true;
        if (stopping_cause_ == EmergencyCause::none) stopping_cause_ = cause;
      }
    }
    forget();
    d.stop = true;
  } else if (latched_) {
    d.stop = true;
  } else if (protective_now) {
    // Protective stop: zero speeds, servo as it is, no latch. An operator's motion is forgotten
    // (send it again); an automatic mode's is kept and resumes once clear for the clear time.
    if (!protective_) {
      ++protective_stops_;
      d.protective_started = true;
      clear_timing_ = false;
    }
    protective_ = true;
    if (!automatic_) forget();
    holding_ = false;
  } else if (held) {
    if (!holding_) {
      holding_ = true;
      hold_since_ = tick;
    } else if (tick - hold_since_ > s_.hold_limit_ticks) {
      forget();
      held = false;
      d.hold_expired = true;
      d.state.main_sensor = 0;
      d.state.watch = 0;
      d.state.safety_mm = 0;
      d.state.sensor = 0;
    }
  } else {
    holding_ = false;
    if (has_request_) {
      d.left = scaled(left_, fraction);
      d.right = scaled(right_, fraction);
    }
  }
  d.source = source_;
  if (!has_request_ && !protective_now && (latched_ || cause != EmergencyCause::none)) protective_ = false;
  d.state.envelope = use_envelope;
  d.state.protective = protective_;
  d.state.protective_stops = protective_stops_;
  const bool granting = has_request_ && (left_ != 0 || right_ != 0) && (d.left != 0 || d.right != 0);
  d.state.granted_pct = static_cast<std::uint8_t>(
      !has_request_ || (left_ == 0 && right_ == 0) ? (d.stop || protective_ ? 0 : 100)
                                                   : (granting ? std::clamp(static_cast<int>(fraction * 100.0), 0, 100) : 0));

  d.state.held = held;
  d.state.latched = latched_;
  d.state.cause = latched_ ? latched_cause_ : cause;
  d.state.enabled = s_.enabled;
  d.state.tick = tick;
  d.state.trips = trips_;
  d.state.clearable = latched_ && !condition_now && !stopping_;
  if (d.state.cause != EmergencyCause::obstacle && !held) d.state.sensor = 0;
  // The ring fires what the remembered request needs (a held request keeps its set).
  const int wanted = has_request_ && (left_ != 0 || right_ != 0) ? main_sensor(left_, right_, s_.wheel_base_mm) : 0;
  d.selection = select_sensors(in.user_table, in.auto_toggle, watch_mask(wanted), (s_.enabled & kDetectUltrasonic) != 0);
  return d;
}

}  // namespace robuter::emergency
