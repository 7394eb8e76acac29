// SPDX-License-Identifier: GPL-3.0-or-later
// Ring firing schedule: nodes in order, a delay before each, results after the time-out.
#include "hal/sim/sonar_timing.hpp"

namespace robuter::sim {

// A node fires when any of its sensors is active (the robot model's wiring; nodes 1..6 here).
int plan_scan(std::span<const bool, kRingSensors> active, const RingTiming& timing, double t0,
              std::span<NodeFiring, kRingNodes> out) {
  bool fires[kRingNodes + 1] = {};
  for (int i = 0; i < kRingSensors; ++i)
    if (active[i]) fires[robot::wired_node(i + 1) + 1] = true;
  int n = 0;
  double t = t0;
  for (int node = 1; node <= kRingNodes; ++node) {
    if (!fires[node]) continue;
    const double fire = t + timing.node_delay;
    const double ready = node_ready_time(fire, timing.timeout);
    out[n++] = {node, fire, ready};
    t = ready;
  }
  return n;
}

}  // namespace robuter::sim
