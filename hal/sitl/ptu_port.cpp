// SPDX-License-Identifier: GPL-3.0-or-later
// Servicing the pan-tilt emulator's byte stream: bounded non-blocking reads and writes per tick.
#include "hal/sitl/ptu_port.hpp"

namespace robuter::hal {

// Why own the stream: the port is the only user of the emulator's pty.
PtuPort::PtuPort(PtuEmulator& emulator, std::unique_ptr<ByteStream> stream)
    : emu_(emulator), stream_(std::move(stream)) {}

// Why: a real unit's replies are lost when nothing listens on the line, so while no host is
// attached the output is dropped instead of piling up for a client that attaches later.
void PtuPort::service() {
  if (!stream_->connected()) {
    if (reopen_in_-- <= 0) {
      reopen_in_ = kReopenTicks;
      stream_->reopen();
    }
    if (!stream_->connected()) {
      emu_.consume_output(emu_.output_size());
      return;
    }
  }
  for (int i = 0; i < kMaxChunks; ++i) {
    const IoResult r = stream_->read(buf_);
    if (r.bytes > 0) {
      bytes_in_ += r.bytes;
      emu_.feed(std::span<const std::uint8_t>(buf_.data(), r.bytes));
    }
    if (r.closed || r.bytes < buf_.size()) break;
  }
  for (int i = 0; i < kMaxChunks && emu_.output_size() > 0; ++i) {
    const std::size_t n = emu_.peek_output(buf_);
    const IoResult w = stream_->write(std::span<const std::uint8_t>(buf_.data(), n));
    emu_.consume_output(w.bytes);
    bytes_out_ += w.bytes;
    if (w.closed || w.bytes < n) break;
  }
}

}  // namespace robuter::hal
