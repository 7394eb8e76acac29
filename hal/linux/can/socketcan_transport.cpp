// SPDX-License-Identifier: GPL-3.0-or-later
// SocketCAN: open with clear start-up errors, non-blocking read/write, error frames → bus state.
#include "hal/linux/can/socketcan_transport.hpp"

#include <fmt/format.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace robuter::hal::can {

BusState apply_error_frame(BusState s, const can_frame& f) {
  if (!(f.can_id & CAN_ERR_FLAG)) return s;
  if (f.can_id & CAN_ERR_BUSOFF) return BusState::off;
  if (f.can_id & CAN_ERR_RESTARTED) return BusState::active;
  if ((f.can_id & CAN_ERR_CRTL) && f.len >= 2) {
    const std::uint8_t c = f.data[1];
    if (c & (CAN_ERR_CRTL_RX_PASSIVE | CAN_ERR_CRTL_TX_PASSIVE)) return BusState::passive;
    if (c & (CAN_ERR_CRTL_RX_WARNING | CAN_ERR_CRTL_TX_WARNING)) return BusState::warning;
    if (c & CAN_ERR_CRTL_ACTIVE) return BusState::active;
  }
  return s;
}

std::string socketcan_error(const std::string& ifname, const char* call, int err) {
  const std::string what = fmt::format("CAN interface '{}': {}: {}", ifname, call, std::strerror(err));
  switch (err) {
    case EAFNOSUPPORT:
      return what + " — this kernel has no SocketCAN (address family AF_CAN/PF_CAN missing): use a kernel "
                    "with CONFIG_CAN and CONFIG_CAN_RAW (modprobe can can_raw), or run with --sim; "
                    "docs/CAN.md explains testing with vcan";
    case EPROTONOSUPPORT:
      return what + " — the CAN_RAW protocol is missing: modprobe can_raw (docs/CAN.md)";
    case ENODEV:
      return what + " — no such network interface: check can.interface, or create a virtual one "
                    "(ip link add dev vcan0 type vcan; ip link set up vcan0; docs/CAN.md)";
    case EPERM:
    case EACCES: return what + " — not permitted";
    default: return what;
  }
}

std::unique_ptr<SocketCanTransport> SocketCanTransport::open(const std::string& ifname, std::string& error) {
  if (ifname.empty() || ifname.size() >= IFNAMSIZ) {
    error = fmt::format("CAN interface '{}': expected a name of 1 to {} characters", ifname, IFNAMSIZ - 1);
    return nullptr;
  }
  const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) {
    error = socketcan_error(ifname, "socket(PF_CAN, SOCK_RAW, CAN_RAW)", errno);
    return nullptr;
  }
  const unsigned index = ::if_nametoindex(ifname.c_str());
  if (index == 0) {
    error = socketcan_error(ifname, "if_nametoindex", errno);
    ::close(fd);
    return nullptr;
  }
  const can_err_mask_t mask = CAN_ERR_CRTL | CAN_ERR_BUSOFF | CAN_ERR_RESTARTED;
  if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &mask, sizeof mask) != 0) {
    error = socketcan_error(ifname, "setsockopt(CAN_RAW_ERR_FILTER)", errno);
    ::close(fd);
    return nullptr;
  }
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = static_cast<int>(index);
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) != 0) {
    error = socketcan_error(ifname, "bind", errno);
    ::close(fd);
    return nullptr;
  }
  return std::unique_ptr<SocketCanTransport>(new SocketCanTransport(fd, "socketcan " + ifname));
}

SocketCanTransport::~SocketCanTransport() {
  if (fd_ >= 0) ::close(fd_);
}

// A full transmit queue (ENOBUFS/EAGAIN) or a down interface fails the send; it never waits.
bool SocketCanTransport::send(const can_frame& f) {
  if (state_ == BusState::off) {
    ++counters_.send_failed;
    return false;
  }
  const ssize_t n = ::write(fd_, &f, sizeof f);
  if (n != static_cast<ssize_t>(sizeof f)) {
    ++counters_.send_failed;
    return false;
  }
  ++counters_.sent;
  return true;
}

bool SocketCanTransport::send_from_signal(const can_frame& f) const noexcept {
  return ::write(fd_, &f, sizeof f) == static_cast<ssize_t>(sizeof f);
}

// Error frames are folded into the state and skipped; a bounded number per call so a storm of
// them cannot hold the caller.
bool SocketCanTransport::receive(can_frame& out) {
  for (int i = 0; i < 32; ++i) {
    can_frame f{};
    const ssize_t n = ::read(fd_, &f, sizeof f);
    if (n != static_cast<ssize_t>(sizeof f)) return false;
    if (f.can_id & CAN_ERR_FLAG) {
      ++counters_.error_frames;
      state_ = apply_error_frame(state_, f);
      continue;
    }
    ++counters_.received;
    out = f;
    return true;
  }
  return false;
}

}  // namespace robuter::hal::can
