// SPDX-License-Identifier: GPL-3.0-or-later
// The in-process bus: fan-out to fixed receive rings, injectable controller state.
#include "hal/linux/can/loopback_bus.hpp"

namespace robuter::hal::can {

// A full queue drops the newest frame, as a socket's receive buffer does.
void LoopbackEndpoint::deliver(const can_frame& f) {
  if (count_ == kQueue) {
    ++overflows_;
    return;
  }
  queue_[(head_ + count_) % kQueue] = f;
  ++count_;
}

bool LoopbackEndpoint::send(const can_frame& f) {
  if (!bus_.carry(this, f)) {
    ++counters_.send_failed;
    return false;
  }
  ++counters_.sent;
  return true;
}

bool LoopbackEndpoint::receive(can_frame& out) {
  if (count_ == 0) return false;
  out = queue_[head_];
  head_ = (head_ + 1) % kQueue;
  --count_;
  ++counters_.received;
  return true;
}

BusState LoopbackEndpoint::bus_state() const { return bus_.state(); }

LoopbackEndpoint& LoopbackBus::attach(const std::string& name) {
  endpoints_.push_back(std::make_unique<LoopbackEndpoint>(*this, name));
  return *endpoints_.back();
}

bool LoopbackBus::carry(const LoopbackEndpoint* from, const can_frame& f) {
  if (state_ == BusState::off) return false;
  for (auto& e : endpoints_)
    if (e.get() != from) e->deliver(f);
  ++frames_;
  return true;
}

}  // namespace robuter::hal::can
