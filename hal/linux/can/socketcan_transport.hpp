// SPDX-License-Identifier: GPL-3.0-or-later
// FrameTransport on a Linux SocketCAN raw socket (PF_CAN, SOCK_RAW, CAN_RAW), with controller error frames.
#pragma once

#include <memory>
#include <string>

#include "hal/linux/can/frame_transport.hpp"

namespace robuter::hal::can {

// The bus state after controller error frame `f` (CAN_ERR_FLAG set) arrives in state `s`:
// CAN_ERR_BUSOFF → off; CAN_ERR_RESTARTED → active; CAN_ERR_CRTL with data[1] RX/TX passive →
// passive, RX/TX warning → warning, CAN_ERR_CRTL_ACTIVE → active. Others keep `s`. Pure.
BusState apply_error_frame(BusState s, const can_frame& f);

// The start-up message for an errno of socket()/bind() on `ifname` (EAFNOSUPPORT: no AF_CAN).
std::string socketcan_error(const std::string& ifname, const char* call, int err);

class SocketCanTransport final : public FrameTransport {
 public:
  // Opens, sets the error filter and non-blocking mode and binds to `ifname`; null and `error`
  // set (docs/CAN.md points at the fix) when the kernel, the interface or the rights are missing.
  static std::unique_ptr<SocketCanTransport> open(const std::string& ifname, std::string& error);
  ~SocketCanTransport() override;
  SocketCanTransport(const SocketCanTransport&) = delete;
  SocketCanTransport& operator=(const SocketCanTransport&) = delete;

  const char* name() const override { return name_.c_str(); }
  int fd() const override { return fd_; }
  bool send(const can_frame& f) override;
  bool receive(can_frame& out) override;
  bool send_from_signal(const can_frame& f) const noexcept override;
  BusState bus_state() const override { return state_; }
  const TransportCounters& counters() const override { return counters_; }

 private:
  SocketCanTransport(int fd, std::string name) : fd_(fd), name_(std::move(name)) {}

  int fd_ = -1;
  std::string name_;          // "socketcan can0"
  BusState state_ = BusState::active;
  TransportCounters counters_;
};

}  // namespace robuter::hal::can
