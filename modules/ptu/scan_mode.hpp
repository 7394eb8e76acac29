// SPDX-License-Identifier: GPL-3.0-or-later
// The process frame of a mode that drives on the pan-tilt's scan (passage finder, door crossing).
#pragma once

#include <cstdint>
#include <utility>

#include "kernel/kernel.hpp"
#include "modules/emergency/mode_process.hpp"
#include "modules/mode_status.hpp"
#include "modules/ptu/scan_view.hpp"
#include "modules/topics.hpp"

namespace robuter::ptu {

// The lifecycle the passage finder and the door crossing share: a run begins when the arbiter
// hands the robot over, ends when it takes it back (or the module's own reason), and each
// activation steps the pure `Logic` on the scan, sends its wish and reports. `Logic` has
// start(tick), fail(reason), active() and step(ScanInputs) → `Output` (a ModeOutput).
template <typename Logic, typename Output>
class ScanMode : public ModeProcess<ModeStatus> {
 public:
  // Runs handed out before the start are not this one's; the status says off.
  bool init(Kernel& k) override {
    claim_.init();
    status_out_.publish(off_status(k.tick()));
    return true;
  }
  void run(Kernel& k) override {
    const std::uint64_t tick = k.tick();
    if (begun()) {
      begin(tick);
    } else if (logic_.active()) {
      const ModeReason why = ended();
      if (why != ModeReason::none) logic_.fail(why);
    }
    publish(k, logic_.step(scans_.now(tick)));
  }
  // A run still going ends with a last step: its zero request and its report.
  void close(Kernel& k) override {
    if (!logic_.active()) return;
    logic_.fail(ModeReason::shutdown);
    publish(k, logic_.step(scans_.closing(k.tick())));
  }

 protected:
  ScanMode(Blackboard& bb, MotionSource me, Writer<MotionRequest> requests, Writer<ModeStatus> status, Logic logic)
      : ModeProcess(bb, me, std::move(requests), std::move(status)), logic_(std::move(logic)), scans_(bb) {}

  // A run handed by the arbiter begins at `tick`: the logic starts (and the module notes what it needs).
  virtual void begin(std::uint64_t tick) = 0;
  // While a run goes on: why it ended, none while it is still this mode's (default: the arbiter's word).
  virtual ModeReason ended() const { return claim_.ended(); }
  // Publishes the status for `o` at `tick` when it changed.
  virtual void report(std::uint64_t tick, const Output& o) = 0;

  Logic logic_;          // the mode's decisions
  ScanView scans_;       // the scan, the pan-tilt's state, odometry

 private:
  // The request (when asked for), then the status.
  void publish(Kernel& k, const Output& o) {
    send(k, o);
    report(k.tick(), o);
  }
};

}  // namespace robuter::ptu
