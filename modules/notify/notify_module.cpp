// SPDX-License-Identifier: GPL-3.0-or-later
// READY=1, WATCHDOG=1 on the periodic path (no allocation, no blocking), STOPPING=1.
#include "modules/notify/notify_module.hpp"

#include "kernel/kernel.hpp"
#include "kernel/log.hpp"

namespace robuter {

NotifyModule::NotifyModule(const std::string& socket, std::uint64_t watchdog_usec)
    : socket_(socket), interval_ns_(static_cast<std::int64_t>(watchdog_usec) * 1000 / 2) {}

void NotifyModule::run(Kernel& k) {
  const std::int64_t now = k.now();
  if (!ready_sent_) {
    ready_sent_ = true;
    if (socket_.send("READY=1\nSTATUS=ticking")) log::info("notify: READY=1 sent");
    else log::warn("notify: READY=1 not taken by NOTIFY_SOCKET");
    last_ping_ns_ = now;
    late_seen_ = k.late_events();
    return;
  }
  const bool on_time = k.rows_on_time() && k.late_events() == late_seen_;
  late_seen_ = k.late_events();
  if (interval_ns_ <= 0 || !on_time || now - last_ping_ns_ < interval_ns_) return;
  if (socket_.send("WATCHDOG=1")) ++watchdog_sent_;
  last_ping_ns_ = now;
}

void NotifyModule::close(Kernel&) { socket_.send("STOPPING=1"); }

}  // namespace robuter
