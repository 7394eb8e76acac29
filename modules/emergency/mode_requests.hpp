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
// its end sends a zero request, once. A request wakes the emergency module so it is judged in
// the tick it was made: every request (gate, doors, demo), or only one with new speeds — a stop
// above all — for a source that repeats its speeds at each activation (the planner's rule; its
// seeded navigation runs are pinned with it). The module claims its topic's writer (it is the
// owner) and hands it here.
class ModeRequests {
 public:
  // Which requests wake the emergency module.
  enum class Wake : std::uint8_t {
    every_request,  // each one
    new_speeds,     // one whose speeds differ from the last sent
  };
  explicit ModeRequests(Writer<MotionRequest> out, Wake wake = Wake::every_request)
      : out_(std::move(out)), wake_(wake) {}
  // The emergency module, woken by requests as `Wake` says (set at composition; none in unit rigs).
  void set_emergency(Process* p) { emergency_ = p; }
  // A run begins: its final zero request is still to come.
  void begin() { sent_stop_ = false; }
  // This activation's wish: `request` with its speeds (cm/s) while the run goes on; without one,
  // the run's final zero request if it has not gone out yet. The arbiter drops either once the
  // robot is no longer this mode's (it stopped the robot then).
  void send(Kernel& k, bool request, std::int32_t left, std::int32_t right) {
    if (!request && sent_stop_) return;
    if (!request) left = right = 0;
    const bool wake = wake_ == Wake::every_request || left != left_ || right != right_;
    const std::uint64_t tick = k.tick();
    out_.modify([&](MotionRequest& r) {
      r.left = left;
      r.right = right;
      r.tick = tick;
    });
    left_ = left;
    right_ = right;
    if (!request) sent_stop_ = true;
    if (wake && emergency_) k.trigger(emergency_);
  }
  // The speeds last sent, cm/s (0 0 before any).
  std::int32_t left() const { return left_; }
  std::int32_t right() const { return right_; }

 private:
  Writer<MotionRequest> out_;    // the mode's motion request topic
  Wake wake_;                    // which requests wake it
  Process* emergency_ = nullptr; // woken by requests
  bool sent_stop_ = true;        // the run's final zero request went out (or no run began)
  std::int32_t left_ = 0;        // cm/s, the last request's left wheel
  std::int32_t right_ = 0;       // cm/s, the last request's right wheel
};

}  // namespace robuter
