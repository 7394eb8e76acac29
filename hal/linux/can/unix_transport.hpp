// SPDX-License-Identifier: GPL-3.0-or-later
// FrameTransport between processes: classic CAN frames as datagrams on a Unix socket (robuterd ↔ robuter-can-nodes).
#pragma once

#include <sys/socket.h>
#include <sys/un.h>

#include <array>
#include <cstddef>
#include <memory>
#include <string>

#include "hal/linux/can/frame_transport.hpp"

namespace robuter::hal::can {

// Datagrams of 1 to 64 struct can_frame (16 bytes each): send() queues, flush() sends the queue
// as one datagram — a Unix datagram socket queues at most net.unix.max_dgram_qlen (10 by default)
// datagrams for its reader, so a frame per datagram would be dropped in every busy tick. The node process (robuter-can-nodes) is the
// server: it binds PATH and answers whoever sent to it last. robuterd is the client: an
// unnamed (autobound) socket that sends to PATH, so either may start first and either may be
// restarted; while the server is missing, sends fail and are counted. The bus state is always
// error-active (a socket has no controller). Never blocks, never allocates once open.
class UnixTransport final : public FrameTransport {
 public:
  enum class Role : std::uint8_t { client, server };
  // Opens the socket for PATH ("unix:" already stripped); null and `error` set on failure. A
  // server replaces a stale socket file at PATH, and removes it when closed.
  static std::unique_ptr<UnixTransport> open(const std::string& path, Role role, std::string& error);
  ~UnixTransport() override;
  UnixTransport(const UnixTransport&) = delete;
  UnixTransport& operator=(const UnixTransport&) = delete;

  const char* name() const override { return name_.c_str(); }
  int fd() const override { return fd_; }
  static constexpr std::size_t kBatch = 64;  // frames per datagram, at most
  bool send(const can_frame& f) override;
  void flush() override;
  bool receive(can_frame& out) override;
  bool send_from_signal(const can_frame& f) const noexcept override;
  BusState bus_state() const override { return BusState::active; }
  const TransportCounters& counters() const override { return counters_; }
  // Server: a client has sent something (there is someone to answer).
  bool has_peer() const { return peer_len_ > 0; }

 private:
  UnixTransport(int fd, Role role, std::string path);

  int fd_ = -1;
  Role role_;
  std::string path_;           // the server's socket path
  std::string name_;           // "unix /path"
  sockaddr_un peer_{};         // where frames go: the server's path, or the client last heard
  socklen_t peer_len_ = 0;     // 0: nobody to send to yet (server before the first datagram)
  std::array<can_frame, kBatch> out_{};  // frames queued by send()
  std::size_t out_count_ = 0;            // frames in out_
  std::array<can_frame, kBatch> in_{};   // the last datagram received
  std::size_t in_count_ = 0, in_pos_ = 0;  // frames in in_, and the next one to hand out
  TransportCounters counters_;
};

}  // namespace robuter::hal::can
