// For the modes that drive the robot (gate, doors, demo): noticing that an emergency or another
// motion source has taken the robot from them.
#pragma once

#include <cstdint>

#include "modules/topics.hpp"

namespace robuter {

// Watches the emergency module's verdict and granted command. Another source's request reaching
// the motors after ours did (an operator's AM, an AW, the planner…) means the operator took
// over; a trip or a latch means an emergency stopped the robot.
class MotionClaim {
 public:
  MotionClaim(Blackboard& bb, MotionSource me);
  // The mode starts driving now.
  void begin();
  // Call every activation while driving; the reason to stop, or none.
  ModeReason interrupted();

 private:
  MotionSource me_;
  Reader<EmergencyState> emergency_;
  Reader<MotionCommand> command_;
  std::uint32_t trips_ = 0;      // EmergencyState.trips at the start
  bool granted_ = false;         // a command of ours has been granted since the start
};

}  // namespace robuter
