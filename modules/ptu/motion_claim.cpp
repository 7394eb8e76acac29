// Trips, latches and the source of the granted command, compared with the start.
#include "modules/ptu/motion_claim.hpp"

namespace robuter {

MotionClaim::MotionClaim(Blackboard& bb, MotionSource me)
    : me_(me), emergency_(bb.emergency.reader()), command_(bb.motion_command.reader()) {}

void MotionClaim::begin() {
  trips_ = emergency_.peek().trips;
  granted_ = false;
}

// Why wait for a first grant: until the emergency module has judged our first request, the
// command in force is still whoever asked before us.
ModeReason MotionClaim::interrupted() {
  const EmergencyState& e = emergency_.peek();
  if (e.latched || e.trips != trips_) return ModeReason::emergency;
  const MotionCommand& c = command_.peek();
  if (c.source == me_) granted_ = true;
  else if (granted_) return ModeReason::operator_motion;
  return ModeReason::none;
}

}  // namespace robuter
