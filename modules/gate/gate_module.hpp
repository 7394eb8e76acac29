// SPDX-License-Identifier: GPL-3.0-or-later
// Passage-finder module (AG / AT): runs GateLogic, asks for motion through the emergency gate.
#pragma once

#include "modules/gate/gate_logic.hpp"
#include "modules/gate/gate_params.hpp"
#include "modules/ptu/scan_mode.hpp"
#include "modules/topics.hpp"

namespace robuter {

// Runs while the arbiter gives it the robot (AG starts a run, AT ends it), reads the pan-tilt scan and the odometry,
// and publishes `gate_motion` (a motion source of the emergency module) and `gate_status` (XD).
// Ends on its own when aligned, or failed: no passage within TIMEOUT, no alignment within the
// allowed manoeuvres, the pan-tilt failing, an emergency, or another motion request taking over.
class GateModule final : public ptu::ScanMode<gate::GateLogic, gate::GateOutput> {
 public:
  // Its own section, the robot model and the pan-tilt's echo geometry (shared with the doors).
  GateModule(Blackboard& bb, const GateConfig& cfg, const robot::RobotModel& model, const ptu::EchoGeometry& echoes);

  const gate::GateLogic& logic() const { return logic_; }

 private:
  // AG (a second AG restarts the search).
  void begin(std::uint64_t tick) override;
  // Publishes the status (on change) and logs the new state.
  void report(std::uint64_t tick, const gate::GateOutput& o) override;

  std::uint64_t started_ = 0;         // tick of the start
};

}  // namespace robuter
