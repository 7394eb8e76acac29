// SPDX-License-Identifier: GPL-3.0-or-later
// A simulated robot that wanders: forward on a slight curve, turning from what its front sensors hear.
#pragma once

#include <array>

#include "hal/sim/rng.hpp"
#include "hal/sim/types.hpp"
#include "hal/sim/sonar_layout.hpp"

namespace robuter::test {

// The benches' wanderer (the simulator's speed, the multipath census): forward on a slight
// curve; turning on the spot for 0.4–2 s once a front sensor hears something within 0.9 m;
// backing off for 1 s from a contact.
class Wanderer {
 public:
  // The wheel speeds for tick k (10 ms) from the ring's last ranges (m, 0 = no echo) and the
  // bumper; a turn's length is drawn from `rng`.
  sim::WheelSpeeds decide(long k, const std::array<double, sim::kRingSensors>& ranges, bool bumper, sim::Rng& rng) {
    auto near = [&](int n) { return ranges[static_cast<std::size_t>(n - 1)] > 0.0 && ranges[static_cast<std::size_t>(n - 1)] < 0.9; };
    const bool blocked = near(22) || near(23) || near(24) || near(1) || near(2) || near(3) || near(4);
    if (bumper && mode_ != Mode::back) {
      mode_ = Mode::back;
      until_ = k + 100;
    } else if (k >= until_) {
      if (mode_ == Mode::back || (mode_ == Mode::forward && blocked)) {
        mode_ = Mode::turn;
        until_ = k + 40 + static_cast<long>(rng.uniform() * 160);
      } else {
        mode_ = Mode::forward;
      }
    }
    switch (mode_) {
      case Mode::forward: return {0.42, 0.38};
      case Mode::turn: return {-0.25, 0.25};
      case Mode::back: return {-0.15, -0.15};
    }
    return {0.0, 0.0};
  }

 private:
  enum class Mode { forward, turn, back } mode_ = Mode::forward;  // the manoeuvre under way
  long until_ = 0;                                                // the tick it ends at
};

}  // namespace robuter::test
