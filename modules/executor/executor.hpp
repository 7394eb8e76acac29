// SPDX-License-Identifier: GPL-3.0-or-later
// Motion executor (seed executor.c): the only module that commands the drive.
#pragma once

#include <cstdint>

#include "hal/api/drive.hpp"
#include "kernel/config.hpp"
#include "kernel/process.hpp"
#include "modules/emergency/mode_requests.hpp"
#include "modules/emergency/motion_claim.hpp"
#include "modules/executor/go_to.hpp"
#include "modules/topics.hpp"

namespace robuter {

class ExecutorModule final : public Process {
 public:
  // Owns `drive` for the life of the module.
  ExecutorModule(Blackboard& bb, hal::Drive& drive, const RobotConfig& robot, const executor::GoToSettings& go_to = {});
  const executor::GoToController& go_to() const { return go_to_; }

  bool init(Kernel& k) override;
  void run(Kernel& k) override;
  void close(Kernel& k) override;

 private:
  // Applies the emergency module's command: stop → zero and servo off; a new grant → speeds.
  void apply_command(bool drive_ok);
  // Decides whether a go-to runs on: new AW, cancellations, one control step per tick.
  void serve_go_to(Kernel& k, const executor::PostureUnits& now);
  // Ends the go-to; `publish_stop` sends the run's final zero request (dropped once the arbiter
  // gave the robot to someone else).
  void end_go_to(Kernel& k, bool publish_stop);

  hal::Drive& drive_;
  RobotConfig robot_;
  executor::GoToController go_to_;
  Reader<MotionCommand> command_;        // what the emergency module grants
  Reader<ServoRequest> servo_;           // ASN / ASF
  Reader<EmergencyState> emergency_;     // trips and latches (a pending ASN ends with one)
  Reader<OdometrySet> odometry_set_;     // AC
  Reader<GoToRequest> go_to_request_;    // AW
  MotionClaim claim_;                    // AW's runs handed by the arbiter, and their end
  Writer<Posture> posture_out_;
  // The go-to's requests (AW), the one rule every source's run follows. No emergency is woken:
  // the emergency module's command wakes this module, and it is judged at its next activation.
  ModeRequests go_to_requests_;
  std::uint32_t applied_seq_ = 0;        // MotionCommand's generation last applied (Posture.command_seq)
  std::uint32_t odometry_seq_ = 0;       // OdometrySet's generation last applied (Posture.odometry_seq)
  std::uint64_t last_go_to_tick_ = ~0ull;  // tick of the last control step (one per tick)
  std::uint64_t servo_asked_tick_ = 0;     // tick of an ASN still waiting for a ready drive
  std::uint32_t servo_asked_trips_ = 0;    // the emergency module's trips when it was asked
  bool servo_pending_ = false;             // an ASN waits for the drive (CiA 402 start-up) and the first grant
};

}  // namespace robuter
