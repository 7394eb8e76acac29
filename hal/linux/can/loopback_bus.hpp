// SPDX-License-Identifier: GPL-3.0-or-later
// An in-process CAN bus: every frame sent by one endpoint reaches every other endpoint; bus state injectable.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "hal/linux/can/frame_transport.hpp"

namespace robuter::hal::can {

class LoopbackBus;

// One node's attachment to a LoopbackBus: a bounded receive queue (like a socket's buffer).
class LoopbackEndpoint final : public FrameTransport {
 public:
  static constexpr std::size_t kQueue = 256;  // frames a slow reader may leave waiting

  LoopbackEndpoint(LoopbackBus& bus, std::string name) : bus_(bus), name_(std::move(name)) {}
  const char* name() const override { return name_.c_str(); }
  int fd() const override { return -1; }
  bool send(const can_frame& f) override;
  bool receive(can_frame& out) override;
  BusState bus_state() const override;
  const TransportCounters& counters() const override { return counters_; }
  // Frames lost because this endpoint's queue was full, count.
  std::uint64_t overflows() const { return overflows_; }
  // Frames waiting to be received.
  std::size_t pending() const { return count_; }

 private:
  friend class LoopbackBus;
  // Called by the bus: appends to the queue or counts an overflow.
  void deliver(const can_frame& f);

  LoopbackBus& bus_;
  std::string name_;
  std::array<can_frame, kQueue> queue_{};  // ring of received frames
  std::size_t head_ = 0;                   // next frame to receive
  std::size_t count_ = 0;                  // frames waiting
  std::uint64_t overflows_ = 0;            // frames dropped on a full queue, count
  TransportCounters counters_;
};

// The bus. Endpoints are created at start-up (attach allocates); sending never allocates.
// Like SocketCAN without CAN_RAW_RECV_OWN_MSGS, a sender does not receive its own frames.
class LoopbackBus {
 public:
  // A new endpoint, valid as long as the bus.
  LoopbackEndpoint& attach(const std::string& name);
  // Injects the controller state every endpoint reports. Bus-off: nothing is delivered and
  // every send fails; error-passive and warning still deliver.
  void set_state(BusState s) { state_ = s; }
  BusState state() const { return state_; }
  // Frames carried so far, count.
  std::uint64_t frames() const { return frames_; }

 private:
  friend class LoopbackEndpoint;
  // Delivers `f` from `from` to every other endpoint; false on bus-off.
  bool carry(const LoopbackEndpoint* from, const can_frame& f);

  std::vector<std::unique_ptr<LoopbackEndpoint>> endpoints_;
  BusState state_ = BusState::active;
  std::uint64_t frames_ = 0;  // frames carried, count
};

}  // namespace robuter::hal::can
