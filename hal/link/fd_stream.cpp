// SPDX-License-Identifier: GPL-3.0-or-later
// Non-blocking read and write with hang-up detection, shared by the descriptor-based links.
#include "hal/link/fd_stream.hpp"

#include <unistd.h>

#include "hal/link/fd_io.hpp"

namespace robuter::hal {

IoResult FdStream::read(std::span<std::uint8_t> out) {
  if (!connected_) return {0, true};
  // EOF, EIO (pty client gone), ENXIO/ENODEV (device removed) all end the session.
  return fd_io_result(FdCall::read, ::read(in_fd_, out.data(), out.size()), [this](int) { connected_ = false; });
}

IoResult FdStream::write(std::span<const std::uint8_t> in) {
  if (!connected_) return {0, true};
  return fd_io_result(FdCall::write, ::write(out_fd_, in.data(), in.size()), [this](int) { connected_ = false; });
}

}  // namespace robuter::hal
