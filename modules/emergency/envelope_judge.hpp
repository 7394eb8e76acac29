// SPDX-License-Identifier: GPL-3.0-or-later
// What the gate asks of the obstacle envelope: how much of a request may be granted now.
#pragma once

#include <cstdint>

#include "modules/emergency/swept_envelope.hpp"

namespace robuter::emergency {

// The gate's view of the envelope (the emergency module's RingEnvelope; fakes in the tests).
class EnvelopeJudge {
 public:
  virtual ~EnvelopeJudge() = default;
  // The verdict on wheel speeds (left, right) cm/s for the robot as it is now; `bumpers` says
  // whether the contact bumpers are armed (they alone watch the blind near field: a creep there
  // needs them).
  virtual EnvelopeVerdict judge(std::int32_t left, std::int32_t right, bool bumpers) = 0;
};

}  // namespace robuter::emergency
