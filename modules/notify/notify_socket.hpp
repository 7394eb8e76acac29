// SPDX-License-Identifier: GPL-3.0-or-later
// A datagram socket to systemd's $NOTIFY_SOCKET, opened at start-up, written without blocking.
#pragma once

#include <sys/socket.h>
#include <sys/un.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace robuter {

// What the service manager asked for, from the environment (sd_notify(3), sd_watchdog_enabled(3)).
struct NotifyEnvironment {
  std::string socket;                 // $NOTIFY_SOCKET: a path, or "@name" (abstract); empty = none
  std::uint64_t watchdog_usec = 0;    // $WATCHDOG_USEC: the service's watchdog time, µs (0 = off)
};

// Reads $NOTIFY_SOCKET, $WATCHDOG_USEC and $WATCHDOG_PID (a watchdog meant for another process
// is off for this one).
NotifyEnvironment notify_environment();

class NotifySocket {
 public:
  // Opens a non-blocking datagram socket for `path` ("@name": abstract); error() says why not.
  explicit NotifySocket(const std::string& path);
  ~NotifySocket();
  NotifySocket(const NotifySocket&) = delete;
  NotifySocket& operator=(const NotifySocket&) = delete;

  const std::optional<std::string>& error() const { return error_; }
  // Sends one message ("READY=1"); never blocks or allocates; false when it was not taken.
  bool send(std::string_view message) noexcept;

 private:
  int fd_ = -1;                // the socket
  sockaddr_un addr_{};         // systemd's address
  socklen_t addr_len_ = 0;     // its length (abstract names are not NUL-terminated)
  std::optional<std::string> error_;
};

}  // namespace robuter
