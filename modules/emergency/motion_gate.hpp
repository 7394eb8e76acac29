// SPDX-License-Identifier: GPL-3.0-or-later
// The request-to-move gate: the emergency module's whole decision, a pure state machine.
#pragma once

#include <cstdint>

#include "modules/emergency/envelope_judge.hpp"
#include "modules/emergency/watchdog_sets.hpp"
#include "modules/topics.hpp"

namespace robuter::emergency {

// Whether a command that would move the robot (or power its servo, start a mode) is taken now:
// while an emergency is latched the gate drops every request, so the link answers such a
// command `error` rather than `ack` — the link's replies follow this one rule.
constexpr bool admits_motion(const EmergencyState& s) { return !s.latched; }

// Everything the gate needs to know, in ticks and mm.
struct MotionGateSettings {
  std::uint8_t enabled = kDetectAll;         // detections on: kDetect* bits (modules/topics.hpp, the vocabulary's)
  std::uint32_t comm_limit_ticks = 18'000;   // link silence that trips, ticks
  std::uint32_t min_safety_mm = 220;         // smallest safety distance, mm
  std::uint32_t safety_mm_per_cm_s = 10;     // safety distance per cm/s of the faster wheel, mm
  std::uint32_t motion_timeout_ticks = 0;    // moving without a new request this long trips, ticks; 0 off
  bool latch = true;                         // a trip holds until a re-enable
  std::uint32_t wheel_base_mm = 600;         // DBW, mm
  std::uint32_t stale_ticks = 300;           // a watch-dog reading older than this counts as missing, ticks
  std::uint32_t hold_limit_ticks = 500;      // a motion held longer than this is forgotten, ticks
  bool envelope = true;                      // obstacles: the swept envelope (false: the seed's watch sets)
  std::uint32_t protective_clear_ticks = 100;  // an automatic request resumes after its envelope is clear this long, ticks
};

// One activation's view of the world.
struct GateInputs {
  std::uint64_t tick = 0;                    // now, ticks
  bool new_request = false;                  // a motion request arrived (the newest one below)
  std::int32_t left = 0;                     // its left wheel speed, cm/s
  std::int32_t right = 0;                    // its right wheel speed, cm/s
  MotionSource source = MotionSource::link;  // who asked
  bool automatic = false;                    // the request is an automatic mode's own (gate, doors, planner, demo)
  bool servo_request = false;                // an ASN/ASF arrived: any motion stops
  bool stop_byte = false;                    // the link's immediate stop byte arrived
  bool reenable = false;                     // a re-enable (XR) arrived
  std::uint32_t bumpers = 0;                 // bumpers pressed, bit per bumper
  std::uint64_t last_message_tick = 0;       // tick of the link's last complete line
  bool drive_fault = false;                  // the drive reports a fault or went silent
  EmergencyCause drive_cause = EmergencyCause::none;  // which (heartbeat, bus…); none = drive_fault
  bool servo_on = false;                     // the drive's servo is on (executor's posture)
  bool at_rest = true;                       // the robot is not moving (odometry unchanged), whatever its set-points
  const UltrasonicRanges* ranges = nullptr;  // the ring's latest ranges (never null in use)
  std::uint32_t user_table = kAllSensors;    // the operator's table (UT), bit s-1 = sensor s
  bool auto_toggle = false;                  // only the watch-dog sensors fire (Uu)
  EnvelopeJudge* envelope = nullptr;         // the swept envelope (used when settings().envelope; null: seed rule)
};

// One activation's verdict.
struct GateDecision {
  EmergencyState state;                      // what the module publishes as `emergency`
  std::int32_t left = 0;                     // granted left wheel speed, cm/s
  std::int32_t right = 0;                    // granted right wheel speed, cm/s
  bool stop = false;                         // emergency: zero and servo off
  MotionSource source = MotionSource::link;  // whose speeds were granted
  std::uint32_t selection = kAllSensors;     // table the ring must fire, bit s-1 = sensor s
  bool tripped = false;                      // this activation stopped a motion (for the log)
  bool hold_expired = false;                 // this activation forgot a motion held too long
  bool cleared = false;                      // this activation cleared a latched emergency
  bool protective_started = false;           // this activation began a protective stop
  bool resumed = false;                      // this activation resumed an automatic request after a protective stop
};

// A wheel speed (cm/s) scaled by the envelope's fraction, truncated towards zero.
std::int32_t scaled(std::int32_t speed, double fraction);

// The seed's emergency() made a state machine with an explicit latch: holds the request to
// move, decides grant / hold / stop every activation. No heap, bounded work.
class MotionGate {
 public:
  explicit MotionGate(const MotionGateSettings& s) : s_(s) {}
  // Decides for one activation.
  GateDecision step(const GateInputs& in);
  // Switches detections on or off (mask bits kDetect*), effective at the next step.
  void set_enabled(std::uint8_t mask) { s_.enabled = static_cast<std::uint8_t>(mask & kDetectAll); }
  std::uint8_t enabled() const { return s_.enabled; }
  const MotionGateSettings& settings() const { return s_; }

 private:
  // Drops the remembered request: the robot stays stopped until a new one arrives.
  void forget();

  MotionGateSettings s_;
  bool has_request_ = false;                   // a request to move is remembered
  std::int32_t left_ = 0;                      // its left wheel speed, cm/s
  std::int32_t right_ = 0;                     // its right wheel speed, cm/s
  MotionSource source_ = MotionSource::link;   // who asked
  std::uint64_t request_tick_ = 0;             // when it arrived, ticks
  bool latched_ = false;                       // a trip waits for a re-enable
  EmergencyCause latched_cause_ = EmergencyCause::none;  // what tripped it
  bool stopping_ = false;                      // a trip stopped a moving robot that has not come to rest yet
  EmergencyCause stopping_cause_ = EmergencyCause::none;  // what tripped it
  bool holding_ = false;                       // the request is held for sensor data
  std::uint64_t hold_since_ = 0;               // when the hold began, ticks
  std::uint32_t trips_ = 0;                    // trips so far
  bool automatic_ = false;                     // the remembered request is an automatic mode's
  bool protective_ = false;                    // a protective stop is in force (obstacle evidence in the envelope)
  bool clear_timing_ = false;                  // the paused automatic request's envelope is clear since clear_since_
  std::uint64_t clear_since_ = 0;              // when it became clear, ticks
  std::uint32_t protective_stops_ = 0;         // protective stops so far
};

}  // namespace robuter::emergency
