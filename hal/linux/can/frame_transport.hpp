// SPDX-License-Identifier: GPL-3.0-or-later
// CAN frame transport: the one interface every CAN frame of robuterd goes through (SocketCAN or loopback).
#pragma once

#include <linux/can.h>

#include <cstdint>

#include "kernel/vocabulary.hpp"

namespace robuter::hal::can {

// The controller's fault confinement state (ISO 11898-1), as the transport last learnt it, with
// SocketCAN's words for logs and docs.
#define ROBUTER_BUS_STATES(X)                                                                          \
  X(active, "error-active")   /* normal */                                                             \
  X(warning, "error-warning") /* an error counter reached 96: still working, reported only */         \
  X(passive, "error-passive") /* a counter reached 128: frames may be delayed or lost */               \
  X(off, "bus-off")           /* the transmit counter reached 256: the controller no longer takes part */
enum class BusState : std::uint8_t { ROBUTER_BUS_STATES(ROBUTER_VOCAB_ENUMERATOR) };
ROBUTER_VOCABULARY(BusState, ROBUTER_BUS_STATES, "bus-off");

// Figures of a transport since it opened.
struct TransportCounters {
  std::uint64_t sent = 0;          // frames handed to the bus, count
  std::uint64_t received = 0;      // data frames received, count
  std::uint64_t send_failed = 0;   // frames not sent (queue full, bus-off, interface down), count
  std::uint64_t error_frames = 0;  // controller error frames received, count
};

// Non-blocking send and receive of classic CAN frames (struct can_frame of linux/can.h) plus the
// bus state. Implementations never block and never allocate after they are open.
class FrameTransport {
 public:
  virtual ~FrameTransport() = default;
  // A short name for logs ("socketcan can0", "loopback drive-1").
  virtual const char* name() const = 0;
  // Descriptor that becomes readable when frames arrive, or -1 when there is none (loopback).
  virtual int fd() const = 0;
  // Queues one frame for the bus now; false when it could not (bus-off, queue full, down).
  virtual bool send(const can_frame& f) = 0;
  // Takes the next received data frame; false when none is waiting. Error frames are consumed
  // here too: they update bus_state() and are never returned.
  virtual bool receive(can_frame& out) = 0;
  // Hands frames queued by send() to the bus now (a transport that batches them: the Unix-socket
  // bus). Called at the end of each backend activation and after an immediate command.
  virtual void flush() {}
  // Sends from a fatal-signal handler: async-signal-safe (one write()/sendto(), no counters);
  // false when the transport cannot (the in-process loopback).
  virtual bool send_from_signal(const can_frame&) const noexcept { return false; }
  virtual BusState bus_state() const = 0;
  virtual const TransportCounters& counters() const = 0;
};

}  // namespace robuter::hal::can
