// SPDX-License-Identifier: GPL-3.0-or-later
// SCHED_FIFO and mlockall, with plain-language messages where the system says no.
#include "kernel/realtime.hpp"

#include <sched.h>
#include <sys/mman.h>

#include <cerrno>
#include <cstring>

#include "kernel/log.hpp"

namespace robuter {

bool apply_realtime(const KernelConfig& cfg) {
  bool ok = true;
  if (cfg.lock_memory) {
    if (mlockall(MCL_CURRENT | MCL_FUTURE) != 0) {
      log::warn("realtime: mlockall refused ({}); memory may page. Grant CAP_IPC_LOCK or raise "
                "'memlock' in /etc/security/limits.conf", std::strerror(errno));
      ok = false;
    } else {
      log::info("realtime: memory locked");
    }
  }
  if (cfg.realtime) {
    sched_param p{};
    p.sched_priority = cfg.rt_priority;
    if (sched_setscheduler(0, SCHED_FIFO, &p) != 0) {
      log::warn("realtime: SCHED_FIFO priority {} refused ({}); running as a normal process. Grant "
                "CAP_SYS_NICE or set 'rtprio' in /etc/security/limits.conf", cfg.rt_priority,
                std::strerror(errno));
      ok = false;
    } else {
      log::info("realtime: SCHED_FIFO priority {}", cfg.rt_priority);
    }
  }
  return ok;
}

}  // namespace robuter
