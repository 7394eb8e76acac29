// SPDX-License-Identifier: GPL-3.0-or-later
// A mode's motion requests to the arbiter: each while its run goes on, then exactly one zero.
#pragma once

#include <cstdint>
#include <utility>

#include "kernel/kernel.hpp"
#include "modules/topics.hpp"

namespace robuter {

// For the modes that drive on their own (gate, doors, demo): the one rule of how a run's wheel
// speeds reach the arbiter. The arbiter remembers a request until a newer one comes, so a run
// that ends without one would leave its last manoeuvre running: its end sends a zero request,
// once. Every request sent wakes the emergency module in the same tick. The module claims its
// topic's writer (it is the owner) and hands it here.
class ModeRequests {
 public:
  explicit ModeRequests(Writer<MotionRequest> out) : out_(std::move(out)) {}
  // The emergency module, woken by each request (set at composition; none in unit rigs).
  void set_emergency(Process* p) { emergency_ = p; }
  // A run begins: its final zero request is still to come.
  void begin() { sent_stop_ = false; }
  // This activation's wish: `request` with its speeds (cm/s) while the run goes on; without one,
  // the run's final zero request if it has not gone out yet. The arbiter drops either once the
  // robot is no longer this mode's (it stopped the robot then).
  void send(Kernel& k, bool request, std::int32_t left, std::int32_t right) {
    if (!request && sent_stop_) return;
    const std::uint64_t tick = k.tick();
    out_.modify([&](MotionRequest& r) {
      r.left = request ? left : 0;
      r.right = request ? right : 0;
      r.tick = tick;
    });
    if (!request) sent_stop_ = true;
    if (emergency_) k.trigger(emergency_);
  }

 private:
  Writer<MotionRequest> out_;    // the mode's motion request topic
  Process* emergency_ = nullptr; // woken by each request
  bool sent_stop_ = true;        // the run's final zero request went out (or no run began)
};

}  // namespace robuter
