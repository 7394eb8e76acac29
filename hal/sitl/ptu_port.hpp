// SPDX-License-Identifier: GPL-3.0-or-later
// The pan-tilt emulator on a byte stream (its pty): what the host writes is fed in, replies written back.
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "hal/api/byte_stream.hpp"
#include "hal/sitl/ptu_emulator.hpp"

namespace robuter::hal {

// Serviced once per tick by the SimStepper; never blocks, bounded work per call.
class PtuPort {
 public:
  static constexpr int kReopenTicks = 10;  // ticks between re-attachment checks while closed

  // The emulator must outlive the port; the port owns the stream.
  PtuPort(PtuEmulator& emulator, std::unique_ptr<ByteStream> stream);

  // Reads what the host wrote, feeds it to the emulator, writes the replies that fit.
  void service();

  ByteStream& stream() { return *stream_; }
  std::uint64_t bytes_in() const { return bytes_in_; }    // bytes received from the host
  std::uint64_t bytes_out() const { return bytes_out_; }  // reply bytes written to the host

 private:
  static constexpr int kMaxChunks = 4;        // reads (and writes) per service() call
  PtuEmulator& emu_;                           // the unit
  std::unique_ptr<ByteStream> stream_;         // its pty (or any byte stream)
  std::array<std::uint8_t, 256> buf_{};        // transfer buffer
  int reopen_in_ = 0;                          // ticks until the next re-attachment check
  std::uint64_t bytes_in_ = 0;                 // bytes received, count
  std::uint64_t bytes_out_ = 0;                // bytes sent, count
};

}  // namespace robuter::hal
