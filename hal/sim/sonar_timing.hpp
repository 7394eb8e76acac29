// SPDX-License-Identifier: GPL-3.0-or-later
// When ring nodes fire and when their results are ready, for a HAL that models firing timing.
#pragma once

#include <array>
#include <span>

#include "hal/sim/sonar_layout.hpp"

namespace robuter::sim {

// Timing of the ring's firing sequence (seed 002 us.c).
struct RingTiming {
  double node_delay = 0.030;  // wait before firing a node other than the last one fired, s
  double timeout = 0.033;     // a fired node's results come back after this time-out, s
};

// One node's firing within a scan.
struct NodeFiring {
  int node = 0;        // node number, 1..6
  double fire = 0.0;   // when it fires, s
  double ready = 0.0;  // when its four readings are available, s
};

// When a node fired at `fire` has its results at the latest: the whole time-out, when one of its
// sensors hears nothing (with every echo in, the last echo_time() after the firing).
constexpr double node_ready_time(double fire, double timeout) { return fire + timeout; }

// Round-trip time of an echo from `range` metres, s (2 r / c).
constexpr double echo_time(double range, double sound_speed) { return 2.0 * range / sound_speed; }

// Plans one scan that starts at t0 and fires, in node order, every node that has an active
// sensor, the way seed 002's read_sensors() does: wait node_delay, fire, wait the time-out for
// the results, wait node_delay, fire the next node... Writes up to six firings into `out` and
// returns how many. `active[i]` is sensor i + 1's active flag.
int plan_scan(std::span<const bool, kRingSensors> active, const RingTiming& timing, double t0,
              std::span<NodeFiring, kRingNodes> out);

// Duration of a full scan of `nodes` nodes, s.
constexpr double scan_duration(int nodes, const RingTiming& t) {
  return nodes * (t.node_delay + t.timeout);
}

}  // namespace robuter::sim
