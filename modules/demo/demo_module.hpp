// SPDX-License-Identifier: GPL-3.0-or-later
// Demonstration module (XT1, or [demo] enabled at start-up): drives the seed's course through the emergency gate.
#pragma once

#include "kernel/config.hpp"
#include "modules/demo/course.hpp"
#include "modules/emergency/mode_process.hpp"
#include "modules/topics.hpp"

namespace robuter {

// Drives the course while the arbiter gives it the robot — from start-up with [demo] enabled, or
// from an operator's XT1 — and publishes `demo_motion` (a motion source of the emergency module:
// obstacles stop it there, as the seed's dem.c relied on emerg.rtm) and `demo_status`. While an
// emergency condition holds at rest it asks for nothing; an operator's command (XT0, AM, ASF, AW,
// XH, Af, AT, the stop byte …) or an emergency trip ends the run, and only XT1 starts a new one.
class DemoModule final : public ModeProcess<DemoStatus> {
 public:
  // Its own section ([demo]) and the robot model (the wheel base), nothing else.
  DemoModule(Blackboard& bb, const DemoConfig& cfg, const robot::RobotModel& robot);

  bool init(Kernel& k) override;
  void run(Kernel& k) override;
  void close(Kernel& k) override;

  const demo::Course& course() const { return course_; }

 private:
  // A run handed by the arbiter begins: the course from its start.
  void begin();

  demo::Course course_;
  bool running_ = false;    // a run handed by the arbiter is going
  Reader<Posture> posture_;
  Reader<UltrasonicRanges> ranges_;
  Reader<EmergencyState> emergency_state_;
  // Publishes the status for the course's output `o` (state `st`, reason `why`).
  void report(const demo::CourseOutput& o, ModeState st, ModeReason why, std::uint64_t tick);
};

}  // namespace robuter
