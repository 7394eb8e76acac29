// SPDX-License-Identifier: GPL-3.0-or-later
// A mode's motion requests to the arbiter: each while its run goes on, then exactly one zero.
#pragma once

#include <cstdint>
#include <utility>

#include "kernel/kernel.hpp"
#include "modules/topics.hpp"

namespace robuter {

// For the sources that drive on their own (gate, doors, demo, the planner, the executor's go-to):
// the one rule of how a run's wheel speeds reach the arbiter. The arbiter remembers a request
// until a newer one comes, so a run that ends without one would leave its last manoeuvre running:
// its end sends a zero request, once. Every request sent wakes the emergency module, so it is
// judged in the tick it was made. The module claims its topic's writer (it is the owner) and
// hands it here.
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
    if (!request) left = right = 0;
    const std::uint64_t tick = k.tick();
    out_.modify([&](MotionRequest& r) {
      r.left = left;
      r.right = right;
      r.tick = tick;
    });
    left_ = left;
    right_ = right;
    if (!request) sent_stop_ = true;
    if (emergency_) k.trigger(emergency_);
  }
  // The speeds last sent, cm/s (0 0 before any).
  std::int32_t left() const { return left_; }
  std::int32_t right() const { return right_; }

 private:
  Writer<MotionRequest> out_;    // the mode's motion request topic
  Process* emergency_ = nullptr; // woken by each request
  bool sent_stop_ = true;        // the run's final zero request went out (or no run began)
  std::int32_t left_ = 0;        // cm/s, the last request's left wheel
  std::int32_t right_ = 0;       // cm/s, the last request's right wheel
};

}  // namespace robuter
