// SPDX-License-Identifier: GPL-3.0-or-later
// Passage-finder module (AG / AT): runs GateLogic, asks for motion through the emergency gate.
#pragma once

#include "kernel/process.hpp"
#include "modules/gate/gate_logic.hpp"
#include "modules/gate/gate_params.hpp"
#include "modules/emergency/mode_requests.hpp"
#include "modules/emergency/motion_claim.hpp"
#include "modules/topics.hpp"

namespace robuter {

// Listens to the `modes` topic (AG starts, AT stops), reads the pan-tilt scan and the odometry,
// and publishes `gate_motion` (a motion source of the emergency module) and `gate_status` (XD).
// Ends on its own when aligned, or failed: no passage within TIMEOUT, no alignment within the
// allowed manoeuvres, the pan-tilt failing, an emergency, or another motion request taking over.
class GateModule final : public Process {
 public:
  // Its own section, the robot model and the pan-tilt's echo geometry (shared with the doors).
  GateModule(Blackboard& bb, const GateConfig& cfg, const robot::RobotModel& model, const ptu::EchoGeometry& echoes);
  // The emergency module, triggered on every request so it is judged in the same tick.
  void set_emergency(Process* p) { requests_.set_emergency(p); }

  bool init(Kernel& k) override;
  void run(Kernel& k) override;
  void close(Kernel& k) override;

  const gate::GateLogic& logic() const { return logic_; }

 private:
  // Publishes the request (when asked for) and the status (on change).
  void publish(Kernel& k, const gate::GateOutput& o);

  gate::GateLogic logic_;
  Reader<PanTiltScan> scan_;
  Reader<ModeStatus> ptu_;
  Reader<Posture> posture_;
  MotionClaim claim_;                 // runs handed by the arbiter (AG), and their end (AT, the operator, an emergency)
  ModeRequests requests_;             // its motion requests, and the final zero one
  Writer<ModeStatus> status_out_;
  std::uint64_t started_ = 0;         // tick of the start
};

}  // namespace robuter
