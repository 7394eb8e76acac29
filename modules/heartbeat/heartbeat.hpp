// SPDX-License-Identifier: GPL-3.0-or-later
// Heartbeat: a proof-of-life process that publishes a beat and logs it at debug level.
#pragma once

#include "kernel/process.hpp"
#include "modules/topics.hpp"

namespace robuter {

class HeartbeatModule final : public Process {
 public:
  explicit HeartbeatModule(Blackboard& bb) : out_(bb.heartbeat.writer()) {}
  void run(Kernel& k) override;

 private:
  Writer<Heartbeat> out_;  // the heartbeat topic
};

}  // namespace robuter
