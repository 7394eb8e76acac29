// SPDX-License-Identifier: GPL-3.0-or-later
// Heartbeat activation.
#include "modules/heartbeat/heartbeat.hpp"

#include "kernel/kernel.hpp"
#include "kernel/log.hpp"

namespace robuter {

// One beat per activation: shows the kernel is alive without any hardware.
void HeartbeatModule::run(Kernel& k) {
  out_.modify([&](Heartbeat& h) {
    ++h.beats;
    h.tick = k.tick();
  });
  log::debug("heartbeat {}", out_.current().beats);
}

}  // namespace robuter
