// SPDX-License-Identifier: GPL-3.0-or-later
// systemd notification from the periodic path: READY=1 once the loop ticks, WATCHDOG=1 while every row runs on time.
#pragma once

#include <cstdint>

#include "kernel/process.hpp"
#include "modules/notify/notify_socket.hpp"

namespace robuter {

// Runs last in every tick (process row "notify", priority 0). Sends READY=1 at its first run
// (the kernel is ticking; drive bring-up is not waited for), then WATCHDOG=1 every half of
// $WATCHDOG_USEC — but only when every row ran at its due tick and none slipped since the last
// one (Kernel::rows_on_time, late_events): a stalled or late loop stops the pings and systemd's
// WatchdogSec= restarts the service. STOPPING=1 at close. Never from another thread.
class NotifyModule final : public Process {
 public:
  NotifyModule(const std::string& socket, std::uint64_t watchdog_usec);
  const std::optional<std::string>& error() const { return socket_.error(); }
  std::uint64_t watchdog_sent() const { return watchdog_sent_; }

  void run(Kernel& k) override;
  void close(Kernel& k) override;

 private:
  NotifySocket socket_;
  std::int64_t interval_ns_ = 0;     // between two WATCHDOG=1, ns (half the watchdog time; 0 = off)
  std::int64_t last_ping_ns_ = 0;    // kernel time of the last WATCHDOG=1, ns
  std::uint64_t late_seen_ = 0;      // Kernel::late_events() at the last look
  bool ready_sent_ = false;          // READY=1 went out
  std::uint64_t watchdog_sent_ = 0;  // WATCHDOG=1 sent, count
};

}  // namespace robuter
