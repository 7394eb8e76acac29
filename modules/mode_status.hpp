// SPDX-License-Identifier: GPL-3.0-or-later
// The rules of a ModeStatus report shared by the modes that publish one (pan-tilt, gate, doors).
#pragma once

#include <cstdint>

#include "modules/topics.hpp"

namespace robuter {

// The report at start-up, at `tick`: off, no run yet.
inline ModeStatus off_status(std::uint64_t tick) {
  return ModeStatus{ModeState::off, ModeReason::none, 0, tick, 0, 0, tick};
}

// `cur` moved on to `state` and `reason` at `tick`; `new_run`: one more run is counted. The
// state's since_tick restarts when the state changed.
inline ModeStatus moved_on(const ModeStatus& cur, ModeState state, ModeReason reason, bool new_run,
                           std::uint64_t tick) {
  ModeStatus s = cur;
  if (new_run) ++s.runs;
  s.state = state;
  s.reason = reason;
  if (cur.state != state) s.since_tick = tick;
  s.tick = tick;
  return s;
}

}  // namespace robuter
