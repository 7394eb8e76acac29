// SPDX-License-Identifier: GPL-3.0-or-later
// Door-crossing module (Ad / Af): runs DoorCrossing, asking the emergency module for the seed's
// lowered detections while it is in the door.
#pragma once

#include <cstdint>

#include "modules/doors/crossing.hpp"
#include "modules/doors/doors_params.hpp"
#include "modules/ptu/scan_mode.hpp"
#include "modules/topics.hpp"

namespace robuter {

class EmergencyModule;

// Starts when the arbiter hands it the robot: on Ad, or when the passage finder reports "aligned"
// and [gate] hand_over is on. It publishes once its wish for [doors] emergency_mask (bumper only,
// as the seed's emerg.on = BUMPER); the emergency module, the mask's only writer, grants it only
// while the crossing owns the robot and is in the door (crossing, waiting, leaving), so every way
// out — crossed, can't cross, Af, an emergency, the operator, the pan-tilt failing, every link
// closed, the time limit, the firmware stopping — gives the detections back at once.
class DoorsModule final : public ptu::ScanMode<doors::DoorCrossing, doors::CrossingOutput> {
 public:
  // Its own section, the robot model and the pan-tilt's echo geometry (shared with the gate).
  DoorsModule(Blackboard& bb, const DoorsConfig& cfg, const robot::RobotModel& model, const ptu::EchoGeometry& echoes,
              EmergencyModule* emergency);

  bool init(Kernel& k) override;

  const doors::DoorCrossing& crossing() const { return logic_; }

 private:
  // Ad, or the passage finder's hand-over.
  void begin(std::uint64_t tick) override;
  // Af, the operator, an emergency — or every link that was open at the start closed.
  ModeReason ended() const override;
  // Every way out passes here with request = false (after the zero request): the status.
  void report(std::uint64_t tick, const doors::CrossingOutput& o) override;

  std::uint8_t crossing_mask_;        // detections kept while in the door
  Reader<LinkStatus> link_;
  Writer<DetectionRequest> detections_out_;  // the wish for lowered detections
  bool had_link_ = false;             // a link was open at the start
};

}  // namespace robuter
