// SPDX-License-Identifier: GPL-3.0-or-later
// The arbiter's authority topic read from a mode's side.
#include "modules/emergency/motion_claim.hpp"

namespace robuter {

MotionClaim::MotionClaim(Blackboard& bb, MotionSource me) : me_(me), authority_(bb.authority.reader()) {}

bool MotionClaim::granted() {
  const MotionAuthority& a = authority_.peek();
  if (a.owner != me_ || a.runs[index()] == run_) return false;
  run_ = a.runs[index()];
  return true;
}

// A newer run of the same source also ends this one (a second AG, XG …): granted() then begins it.
ModeReason MotionClaim::ended() const {
  const MotionAuthority& a = authority_.peek();
  if (a.owner == me_ && a.runs[index()] == run_) return ModeReason::none;
  if (lent()) return ModeReason::none;
  if (a.runs[index()] != run_) return ModeReason::operator_motion;
  const ModeReason why = a.ended[index()];
  return why == ModeReason::none ? ModeReason::operator_motion : why;
}

bool MotionClaim::lent() const {
  const MotionAuthority& a = authority_.peek();
  return a.lent_by == me_ && a.runs[index()] == run_ && run_ != 0;
}

}  // namespace robuter
