// The kernel process that advances the simulated world to the kernel's clock each tick.
#pragma once

#include "hal/sitl/sim_robot.hpp"
#include "kernel/kernel.hpp"

namespace robuter::hal {

// Runs first in every tick (highest priority), so modules see the world as of this tick.
class SimStepper final : public Process {
 public:
  explicit SimStepper(SimRobot& r) : r_(r) {}
  bool init(Kernel& k) override {
    origin_ = k.now();
    return true;
  }
  void run(Kernel& k) override { r_.advance_to(static_cast<double>(k.now() - origin_) * 1e-9); }

 private:
  SimRobot& r_;
  Nanos origin_ = 0;  // kernel time of simulated time 0, ns
};

}  // namespace robuter::hal
