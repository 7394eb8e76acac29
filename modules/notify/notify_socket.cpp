// SPDX-License-Identifier: GPL-3.0-or-later
// The notify socket: environment, address (path or abstract), non-blocking sendto.
#include "modules/notify/notify_socket.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <cstring>

namespace robuter {

NotifyEnvironment notify_environment() {
  NotifyEnvironment e;
  if (const char* s = std::getenv("NOTIFY_SOCKET")) e.socket = s;
  const char* usec = std::getenv("WATCHDOG_USEC");
  const char* pid = std::getenv("WATCHDOG_PID");
  if (usec != nullptr && (pid == nullptr || std::strtoll(pid, nullptr, 10) == ::getpid()))
    e.watchdog_usec = std::strtoull(usec, nullptr, 10);
  return e;
}

NotifySocket::NotifySocket(const std::string& path) {
  if (path.empty() || path.size() >= sizeof addr_.sun_path || (path[0] != '/' && path[0] != '@')) {
    error_ = "NOTIFY_SOCKET '" + path + "': expected an absolute path or @name of at most " +
             std::to_string(sizeof addr_.sun_path - 1) + " bytes";
    return;
  }
  fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd_ < 0) {
    error_ = std::string("NOTIFY_SOCKET: socket(AF_UNIX, SOCK_DGRAM): ") + std::strerror(errno);
    return;
  }
  addr_.sun_family = AF_UNIX;
  std::memcpy(addr_.sun_path, path.data(), path.size());
  if (path[0] == '@') addr_.sun_path[0] = '\0';
  addr_len_ = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + path.size() + (path[0] == '@' ? 0 : 1));
}

NotifySocket::~NotifySocket() {
  if (fd_ >= 0) ::close(fd_);
}

bool NotifySocket::send(std::string_view message) noexcept {
  if (fd_ < 0) return false;
  return ::sendto(fd_, message.data(), message.size(), MSG_DONTWAIT | MSG_NOSIGNAL,
                  reinterpret_cast<const sockaddr*>(&addr_), addr_len_) == static_cast<ssize_t>(message.size());
}

}  // namespace robuter
