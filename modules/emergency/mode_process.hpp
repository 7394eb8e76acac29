// SPDX-License-Identifier: GPL-3.0-or-later
// The frame of a mode that drives on its own: its runs handed by the arbiter, its requests, its status.
#pragma once

#include <cstdint>
#include <utility>

#include "kernel/process.hpp"
#include "modules/emergency/mode_output.hpp"
#include "modules/emergency/mode_requests.hpp"
#include "modules/emergency/motion_claim.hpp"
#include "modules/topics.hpp"

namespace robuter {

// For the modes that drive on their own (gate, doors, demo, the planner): the robot comes to them
// as runs the arbiter hands out (MotionClaim), their wheel speeds go out through ModeRequests,
// their state through a status topic of type `Status`. The module claims its topics' writers (it is their
// owner) and hands them here.
template <typename Status>
class ModeProcess : public Process {
 public:
  // The emergency module, triggered by requests (ModeRequests::Wake) so they are judged in the
  // tick they were made (set at composition; none in unit rigs).
  void set_emergency(Process* p) { requests_.set_emergency(p); }

 protected:
  ModeProcess(Blackboard& bb, MotionSource me, Writer<MotionRequest> requests, Writer<Status> status,
              ModeRequests::Wake wake = ModeRequests::Wake::every_request)
      : claim_(bb, me), requests_(std::move(requests), wake), status_out_(std::move(status)) {}

  // True once for each new run the arbiter hands to this mode: begin it now (its final zero
  // request is still to come).
  bool begun() {
    if (!claim_.granted()) return false;
    requests_.begin();
    return true;
  }
  // Sends this activation's wish (ModeRequests::send).
  void send(Kernel& k, const ModeOutput& o) { requests_.send(k, o.request, o.left, o.right); }

  MotionClaim claim_;          // runs handed by the arbiter, and their end
  ModeRequests requests_;      // its motion requests, and the final zero one
  Writer<Status> status_out_;  // its status (XD)
};

}  // namespace robuter
