// SPDX-License-Identifier: GPL-3.0-or-later
// The built-in pan-tilt sweep: turn round at the limits, fire channel 7 on 5° marks.
#include "hal/sitl/ptu_sweep.hpp"

#include <cmath>

namespace robuter::hal {

// Why every tick: reading the result as soon as it is ready keeps the next 30 ms slot free.
void PtuSweep::run() {
  PtuEmulator& u = r_.ptu();
  const PtuParams& p = u.params();
  if (!started_) {
    u.command_speed(p.speed);
    u.command_position(p.min_position);  // the seed's init_ptu: move_ptu(-1755, SPEED)
    started_ = true;
  }
  if (!u.moving()) {
    u.command_position(u.target() == p.min_position ? p.max_position : p.min_position);
    ++turns_;
  }
  NodeRanges out{};
  if (pending_ && r_.ring().read(kPanTiltChannel, out)) {
    pending_ = false;
    ++readings_;
  }
  const double now = r_.time();
  if (now + 1e-9 < next_s_) return;
  next_s_ = now + kPeriod;
  if (pending_) return;
  const double angle = u.angle_deg();
  const double mark = std::round(angle / 5.0);
  const int sector = static_cast<int>(mark);
  if (std::abs(angle - 5.0 * mark) > kTolerance || sector == last_sector_) return;
  if (r_.ring().fire(kPanTiltChannel, 0x3)) {
    pending_ = true;
    last_sector_ = sector;
    ++firings_;
  }
}

}  // namespace robuter::hal
