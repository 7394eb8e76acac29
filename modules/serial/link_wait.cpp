// SPDX-License-Identifier: GPL-3.0-or-later
// Read-your-writes: after a request that another module carries out, the link handles no
// further line until that owner has run (docs/PROTOCOL.md, "What `ack` means").
#include "modules/serial/link_port.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>

#include "kernel/kernel.hpp"
#include "modules/emergency/motion_gate.hpp"
#include "modules/localise/map_frame.hpp"
#include "modules/planner/map_bounds.hpp"

namespace robuter {

using protocol::PortResult;

// Generations only grow; the owners publish on every run (state, posture), so "changed since
// the start of the wait" is "ran since". The executor must also have applied the emergency
// module's latest command (which it triggers the executor for): with the default priorities it
// runs right after the emergency module, but a refused trigger or another table may delay it.
// The executor is run for the wait only when the request is its own (AS, AC): an extra posture
// sample changes nothing else, but the emergency module's at-rest test compares postures of
// different ticks, so it is not asked for without need.
bool LinkPort::waiting() {
  if (!waiting_) return false;
  if (emergency_ran() && executor_done() && localise_done()) {
    waiting_ = false;
    return false;
  }
  trigger_owners();
  return true;
}

bool LinkPort::emergency_ran() const { return !emergency_runs_ || emergency_.generation() != wait_emergency_gen_; }

bool LinkPort::executor_done() const {
  if (!executor_runs_) return true;
  if (wait_executor_ && posture_.generation() == wait_posture_gen_) return false;
  return posture_.peek().command_seq == command_.generation();
}

bool LinkPort::localise_done() const {
  if (!localise_runs_) return true;
  const Localisation& l = localisation_.peek();
  return l.odometry_seq == w_.odometry.generation() && l.request_seq == w_.localise.generation();
}

// The owners must run after the latest request: a new one restarts the wait from now.
void LinkPort::await_owners(bool executor) {
  if (!waiting_) wait_executor_ = false;
  waiting_ = true;
  wait_executor_ = wait_executor_ || executor;
  wait_emergency_gen_ = emergency_.generation();
  wait_posture_gen_ = posture_.generation();
  trigger_owners();
}

void LinkPort::trigger_owners() const {
  if (!kernel_) return;
  if (!emergency_ran()) kernel_->trigger(emergency_process_);
  if (executor_runs_ && !executor_done()) kernel_->trigger(executor_process_);
  if (localise_runs_ && !localise_done()) kernel_->trigger(localise_process_);
}

bool LinkPort::revive_link() {
  const std::uint64_t t = tick(), last = w_.status.current().last_message_tick;
  if (!(t > last && t - last > s_.comm_limit_ticks)) return false;
  message_received();
  await_owners(false);
  return true;
}

void LinkPort::wake_emergency() { await_owners(false); }

}  // namespace robuter
