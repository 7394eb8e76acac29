// SPDX-License-Identifier: GPL-3.0-or-later
// Demonstration module (XT1, or [demo] enabled at start-up): drives the seed's course through the emergency gate.
#pragma once

#include "kernel/config.hpp"
#include "kernel/process.hpp"
#include "modules/demo/course.hpp"
#include "modules/emergency/mode_requests.hpp"
#include "modules/emergency/motion_claim.hpp"
#include "modules/topics.hpp"

namespace robuter {

// Drives the course while the arbiter gives it the robot — from start-up with [demo] enabled, or
// from an operator's XT1 — and publishes `demo_motion` (a motion source of the emergency module:
// obstacles stop it there, as the seed's dem.c relied on emerg.rtm) and `demo_status`. While an
// emergency condition holds at rest it asks for nothing; an operator's command (XT0, AM, ASF, AW,
// XH, Af, AT, the stop byte …) or an emergency trip ends the run, and only XT1 starts a new one.
class DemoModule final : public Process {
 public:
  // Its own section ([demo]) and the robot model (the wheel base), nothing else.
  DemoModule(Blackboard& bb, const DemoConfig& cfg, const robot::RobotModel& robot);
  // The emergency module, triggered on every request so it is judged in the same tick.
  void set_emergency(Process* p) { requests_.set_emergency(p); }

  bool init(Kernel& k) override;
  void run(Kernel& k) override;
  void close(Kernel& k) override;

  const demo::Course& course() const { return course_; }

 private:
  demo::Course course_;
  bool running_ = false;    // a run handed by the arbiter is going
  MotionClaim claim_;       // runs handed by the arbiter, and their end
  Reader<Posture> posture_;
  Reader<UltrasonicRanges> ranges_;
  Reader<EmergencyState> emergency_state_;
  ModeRequests requests_;   // its motion requests, and the final zero one
  Writer<DemoStatus> status_out_;
  // Publishes the status for the course's output `o` (state `st`, reason `why`).
  void report(const demo::CourseOutput& o, ModeState st, ModeReason why, std::uint64_t tick);
};

}  // namespace robuter
