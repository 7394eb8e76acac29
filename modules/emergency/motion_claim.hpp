// SPDX-License-Identifier: GPL-3.0-or-later
// A mode's view of the motion arbiter: when the robot is handed to it, and why its run ended.
#pragma once

#include <cstdint>

#include "modules/topics.hpp"

namespace robuter {

// For the sources that drive on their own (gate, doors, planner, demo, the executor's go-to):
// they start when the arbiter hands them the robot and stop the moment it takes it back.
class MotionClaim {
 public:
  MotionClaim(Blackboard& bb, MotionSource me);
  // Runs handed out before the start are not this process's to begin.
  void init() { run_ = authority_.peek().runs[index()]; }
  // True once for each new run the arbiter hands to this source: begin it now.
  bool granted();
  // While a run is going: why it ended — the operator took the robot (`operator_motion`), its own
  // stop command (`cancelled`), an emergency — or none while it is still this source's.
  ModeReason ended() const;
  // While a run is going: the robot is lent to another mode (the planner's, to the door crossing
  // at a narrow door): the run goes on, waiting for it back.
  bool lent() const;
  // The run this source began last (0: none).
  std::uint32_t run() const { return run_; }

 private:
  std::size_t index() const { return static_cast<std::size_t>(me_); }

  MotionSource me_;                    // who this is
  Reader<MotionAuthority> authority_;  // the arbiter's decision
  std::uint32_t run_ = 0;              // the run begun last
};

}  // namespace robuter
