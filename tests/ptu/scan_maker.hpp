// SPDX-License-Identifier: GPL-3.0-or-later
// Test helper: a complete pan-tilt scan of a world, as the firmware would hold it after a sweep
// with the robot standing still at a pose (the simulator's sonar model, the seed's correction).
#pragma once

#include <memory>
#include <string>

#include "hal/sim/sonar_layout.hpp"
#include "hal/sim/world.hpp"
#include "modules/topics.hpp"

namespace robuter::test {

class ScanMaker {
 public:
  // Loads `world_file`; ok() tells whether it did. `noise_seed` ≠ 0 adds the simulator's noise.
  explicit ScanMaker(const std::string& world_file, std::uint64_t noise_seed = 0);
  ~ScanMaker();
  bool ok() const { return world_ != nullptr; }
  // The scan from the robot at (x, y) m heading `heading_deg` (world frame); the odometry in
  // each sector's pose is the world pose.
  PanTiltScan scan(double x, double y, double heading_deg, std::uint64_t tick = 1);
  const sim::World& world() const { return *world_; }

 private:
  std::unique_ptr<sim::World> world_;
  std::unique_ptr<sim::SonarModel> model_;
  std::unique_ptr<sim::Rng> rng_;
};

}  // namespace robuter::test
