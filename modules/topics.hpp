// Every blackboard topic of the firmware: one small struct each, with its owner module.
// The table in docs/ARCHITECTURE.md lists writer and readers; keep the two in step.
#pragma once

#include <array>
#include <cstdint>

#include "kernel/blackboard.hpp"

namespace robuter {

// Owner modules (each defined in modules/<name>/); being named here makes them the writers.
class HeartbeatModule;

// Proof of life of the kernel: a count per second (until the simulator and link land, the
// only thing `make run` shows).
struct Heartbeat {
  std::uint64_t beats = 0;   // heartbeats since start
  std::uint64_t tick = 0;    // tick of the last beat
};

// The firmware's shared state: one Topic per struct, owner fixed by the type.
struct Blackboard {
  Topic<Heartbeat, HeartbeatModule> heartbeat;
};

}  // namespace robuter
