// SPDX-License-Identifier: GPL-3.0-or-later
// HAL: a byte stream (command link or pan-tilt port): non-blocking, with a descriptor to wait on.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace robuter::hal {

// A change in who holds a shared stream (a pty's clients), reported in the order it happened.
enum class ClientEvent : std::uint8_t {
  none,           // nothing new
  session_start,  // a client opened it while none held it: a fresh session begins
  session_end,    // its last client closed it: serve what that client wrote, then end the session
  shared,         // a second program opened it while a client held it: both read the replies
};

// Result of a read or write: bytes moved, or what stopped it.
struct IoResult {
  std::size_t bytes = 0;   // bytes read or written
  bool closed = false;     // the peer went away (EOF, hang-up, device removed)
};

class ByteStream {
 public:
  virtual ~ByteStream() = default;
  // A short name for logs ("pty /tmp/robuter.pty", "serial /dev/ttyUSB0").
  virtual const char* name() const = 0;
  // Descriptor that becomes readable when bytes arrive, or -1 when none (closed).
  virtual int fd() const = 0;
  // Reads what is available now, never blocks.
  virtual IoResult read(std::span<std::uint8_t> out) = 0;
  // Writes what fits now, never blocks.
  virtual IoResult write(std::span<const std::uint8_t> in) = 0;
  // Called periodically while closed: tries to become usable again (client reattached,
  // device back). True when usable.
  virtual bool reopen() = 0;
  // True while a peer is attached and the stream is usable.
  virtual bool connected() const = 0;
  // Why a device was last lost, for logs ("hung up", "Input/output error"…); null when the
  // stream has no device that can be lost (a pty client leaving is not a loss).
  virtual const char* loss_reason() const { return nullptr; }
  // The next client event since the last call (streams without shared clients: none).
  virtual ClientEvent next_client_event() { return ClientEvent::none; }
  // A second descriptor that becomes readable when a client event is waiting, or -1.
  virtual int event_fd() const { return -1; }
  // True while a client holds the stream (a pty's slave is open); for a device or a pipe,
  // while it is usable.
  virtual bool client_present() const { return connected(); }
  // Drops replies written to the stream that its client has not read yet (a pty: the slave's
  // input queue), so a new client never reads the previous one's replies.
  virtual void discard_unread_output() {}
};

}  // namespace robuter::hal
