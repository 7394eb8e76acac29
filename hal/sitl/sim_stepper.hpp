// SPDX-License-Identifier: GPL-3.0-or-later
// The kernel process that advances the simulated world to the kernel's clock each tick.
#pragma once

#include <memory>
#include <optional>

#include "hal/sitl/odometry_frame.hpp"
#include "hal/sitl/ptu_port.hpp"
#include "hal/sitl/ptu_sweep.hpp"
#include "hal/sitl/sim_robot.hpp"
#include "kernel/kernel.hpp"

namespace robuter::hal {

// Runs first in every tick (highest priority), so modules see the world as of this tick. It
// also services the pan-tilt emulator's byte stream (the in-process pipe to the PTU module by
// default, or its pty with robuterd --ptu-pty) and, with --ptu-sweep, drives the built-in sweep.
class SimStepper final : public Process {
 public:
  explicit SimStepper(SimRobot& r) : r_(r) {}
  // Serves the pan-tilt emulator on `stream` (its pty, or its end of the in-process pipe) from
  // now on; start-up only.
  void attach_ptu(std::unique_ptr<ByteStream> stream) { ptu_port_.emplace(r_.ptu(), std::move(stream)); }
  // Sweeps the pan-tilt and fires its sonars without a PTU module; start-up only.
  void set_ptu_sweep(bool on) {
    if (on) ptu_sweep_.emplace(r_);
    else ptu_sweep_.reset();
  }
  // Publishes, every tick, where the odometry frame lies in the world (the planner's pictures
  // are drawn in the world frame with it); start-up only.
  void publish_frame(OdometryFrame* frame) { frame_ = frame; }
  PtuPort* ptu_port() { return ptu_port_ ? &*ptu_port_ : nullptr; }
  PtuSweep* ptu_sweep() { return ptu_sweep_ ? &*ptu_sweep_ : nullptr; }

  bool init(Kernel& k) override {
    origin_ = k.now();
    return true;
  }
  // Why this order: the world (robot and pan axis) first, then the unit answers what the host
  // wrote during the last tick, then the sweep acts on the new angle.
  void run(Kernel& k) override {
    r_.advance_to(static_cast<double>(k.now() - origin_) * 1e-9);
    if (frame_ != nullptr) frame_->publish(r_.robot().pose(), r_.robot().odometry());
    if (ptu_port_) ptu_port_->service();
    if (ptu_sweep_) ptu_sweep_->run();
  }

 private:
  SimRobot& r_;
  Nanos origin_ = 0;                    // kernel time of simulated time 0, ns
  std::optional<PtuPort> ptu_port_;     // the emulator's stream (pipe or pty), when wired
  std::optional<PtuSweep> ptu_sweep_;   // the built-in sweep, when asked for
  OdometryFrame* frame_ = nullptr;      // where to publish the odometry frame, if anywhere
};

}  // namespace robuter::hal
