// SPDX-License-Identifier: GPL-3.0-or-later
// Unix datagram CAN transport: server binds the path and answers its last client; client sends to the path.
#include "hal/linux/can/unix_transport.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstring>

namespace robuter::hal::can {

namespace {
socklen_t fill(sockaddr_un& a, const std::string& path) {
  a = sockaddr_un{};
  a.sun_family = AF_UNIX;
  std::memcpy(a.sun_path, path.data(), path.size());
  return static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + path.size() + 1);
}
}  // namespace

UnixTransport::UnixTransport(int fd, Role role, std::string path)
    : fd_(fd), role_(role), path_(std::move(path)), name_("unix " + path_) {
  if (role_ == Role::client) peer_len_ = fill(peer_, path_);
}

std::unique_ptr<UnixTransport> UnixTransport::open(const std::string& path, Role role, std::string& error) {
  if (path.empty() || path[0] != '/' || path.size() >= sizeof(sockaddr_un::sun_path)) {
    error = "CAN bus unix:" + path + ": expected an absolute path of at most 107 bytes";
    return nullptr;
  }
  const int fd = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd < 0) {
    error = "CAN bus unix:" + path + ": socket(AF_UNIX, SOCK_DGRAM): " + std::strerror(errno);
    return nullptr;
  }
  sockaddr_un a{};
  socklen_t len = 0;
  if (role == Role::server) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) == 0 && S_ISSOCK(st.st_mode)) ::unlink(path.c_str());  // a stale socket
    len = fill(a, path);
  } else {
    a.sun_family = AF_UNIX;  // autobind: an abstract address of the kernel's choosing, for the answers
    len = sizeof(sa_family_t);
  }
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&a), len) != 0) {
    error = "CAN bus unix:" + path + ": bind: " + std::strerror(errno);
    ::close(fd);
    return nullptr;
  }
  return std::unique_ptr<UnixTransport>(new UnixTransport(fd, role, path));
}

UnixTransport::~UnixTransport() {
  if (fd_ >= 0) ::close(fd_);
  if (role_ == Role::server) ::unlink(path_.c_str());
}

bool UnixTransport::send(const can_frame& f) {
  if (out_count_ == out_.size()) flush();
  out_[out_count_++] = f;
  return true;
}

void UnixTransport::flush() {
  if (out_count_ == 0) return;
  const std::size_t bytes = out_count_ * sizeof(can_frame);
  const bool ok = peer_len_ > 0 && ::sendto(fd_, out_.data(), bytes, MSG_DONTWAIT | MSG_NOSIGNAL,
                                            reinterpret_cast<const sockaddr*>(&peer_), peer_len_) ==
                                       static_cast<ssize_t>(bytes);
  // No peer yet (ENOENT, ECONNREFUSED) or its queue full (EAGAIN): the frames are lost, counted.
  (ok ? counters_.sent : counters_.send_failed) += out_count_;
  out_count_ = 0;
}

bool UnixTransport::send_from_signal(const can_frame& f) const noexcept {
  if (peer_len_ == 0) return false;
  return ::sendto(fd_, &f, sizeof f, MSG_DONTWAIT | MSG_NOSIGNAL, reinterpret_cast<const sockaddr*>(&peer_), peer_len_) ==
         static_cast<ssize_t>(sizeof f);
}

// The server learns its client from each datagram (a restarted robuterd has a new address).
bool UnixTransport::receive(can_frame& out) {
  for (int i = 0; i < 32 && in_pos_ == in_count_; ++i) {
    sockaddr_un from{};
    socklen_t from_len = sizeof from;
    const ssize_t n = ::recvfrom(fd_, in_.data(), sizeof in_, MSG_DONTWAIT, reinterpret_cast<sockaddr*>(&from), &from_len);
    if (n < 0) return false;
    if (n == 0 || n % static_cast<ssize_t>(sizeof(can_frame)) != 0) continue;  // not frames: dropped
    if (role_ == Role::server && from_len > sizeof(sa_family_t)) {
      peer_ = from;
      peer_len_ = from_len;
    }
    in_count_ = static_cast<std::size_t>(n) / sizeof(can_frame);
    in_pos_ = 0;
  }
  if (in_pos_ == in_count_) return false;
  out = in_[in_pos_++];
  ++counters_.received;
  return true;
}

}  // namespace robuter::hal::can
