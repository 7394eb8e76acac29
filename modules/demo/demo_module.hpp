// Demonstration module ([demo] enabled): drives the seed's course through the emergency gate.
#pragma once

#include "kernel/config.hpp"
#include "kernel/process.hpp"
#include "modules/demo/course.hpp"
#include "modules/topics.hpp"

namespace robuter {

// When enabled, starts the course at start-up and publishes `demo_motion` (a motion source of
// the emergency module: obstacles stop it there, as the seed's dem.c relied on emerg.rtm) and
// `demo_status`. While an emergency holds it asks for nothing; it carries on once cleared.
class DemoModule final : public Process {
 public:
  DemoModule(Blackboard& bb, const Config& cfg);
  // The emergency module, triggered on every request so it is judged in the same tick.
  void set_emergency(Process* p) { emergency_ = p; }

  bool init(Kernel& k) override;
  void run(Kernel& k) override;
  void close(Kernel& k) override;

  const demo::Course& course() const { return course_; }

 private:
  demo::Course course_;
  bool enabled_;
  Reader<Posture> posture_;
  Reader<UltrasonicRanges> ranges_;
  Reader<EmergencyState> emergency_state_;
  Writer<MotionRequest> motion_out_;
  Writer<DemoStatus> status_out_;
  Process* emergency_ = nullptr;
  bool sent_stop_ = false;  // the final zero request went out
};

}  // namespace robuter
