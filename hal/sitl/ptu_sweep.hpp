// SPDX-License-Identifier: GPL-3.0-or-later
// robuterd --ptu-sweep: a sweep of the emulated unit and its sonars without the PTU module or the protocol (the bench, pictures).
#pragma once

#include <cstdint>

#include "hal/sitl/sim_robot.hpp"

namespace robuter::hal {

// Seed ptu.c's behaviour without the serial protocol: sweep between the unit's limits at its
// power-up speed (1500 positions/s), turning round at each end, and every 30 ms fire both
// pan-tilt sonars (channel 7) when the angle is within 1° of a multiple of 5° (each 5° sector
// once per pass). Run once per tick after the world has advanced.
class PtuSweep {
 public:
  static constexpr double kPeriod = 0.030;   // the seed's PTU process period, s
  static constexpr double kTolerance = 1.0;  // firing window around a multiple of 5°, degrees

  explicit PtuSweep(SimRobot& r) : r_(r) {}
  void run();

  std::uint64_t firings() const { return firings_; }  // channel-7 firings so far
  std::uint64_t readings() const { return readings_; } // channel-7 results read so far
  std::uint64_t turns() const { return turns_; }        // sweep ends reached

 private:
  SimRobot& r_;                 // the robot whose unit and ring are driven
  bool started_ = false;        // the first sweep has been commanded
  bool pending_ = false;        // a firing waits to be read
  double next_s_ = 0.0;         // simulated time of the next 30 ms activation, s
  int last_sector_ = 1000;      // multiple of 5° last fired at, degrees/5 (1000: none yet)
  std::uint64_t firings_ = 0;   // firings, count
  std::uint64_t readings_ = 0;  // readings taken, count
  std::uint64_t turns_ = 0;     // ends reached, count
};

}  // namespace robuter::hal
