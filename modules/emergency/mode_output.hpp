// SPDX-License-Identifier: GPL-3.0-or-later
// One activation's wish of a mode that drives on its own: the wheel speeds to request, the state to report.
#pragma once

#include <cstdint>

#include "modules/topics.hpp"

namespace robuter {

// What the passage finder's and the door crossing's logic decide each activation; each adds the
// figures of its own report. The speeds go out through ModeRequests, the state and reason as the
// mode's ModeStatus.
struct ModeOutput {
  std::int32_t left = 0;                 // wheel speeds to request, cm/s
  std::int32_t right = 0;                // cm/s
  bool request = false;                  // publish the speeds (false once ended)
  ModeState state = ModeState::off;      // what the mode reports (its states: see its logic)
  ModeReason reason = ModeReason::none;  // why it failed
};

}  // namespace robuter
