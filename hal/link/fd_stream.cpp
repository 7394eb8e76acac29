// SPDX-License-Identifier: GPL-3.0-or-later
// Non-blocking read and write with hang-up detection, shared by the descriptor-based links.
#include "hal/link/fd_stream.hpp"

#include <unistd.h>

#include <cerrno>

namespace robuter::hal {

IoResult FdStream::read(std::span<std::uint8_t> out) {
  if (!connected_) return {0, true};
  const ssize_t n = ::read(in_fd_, out.data(), out.size());
  if (n > 0) return {static_cast<std::size_t>(n), false};
  if (n < 0 && (errno == EAGAIN || errno == EINTR)) return {0, false};
  connected_ = false;  // EOF, EIO (pty client gone), ENXIO/ENODEV (device removed)
  return {0, true};
}

IoResult FdStream::write(std::span<const std::uint8_t> in) {
  if (!connected_) return {0, true};
  const ssize_t n = ::write(out_fd_, in.data(), in.size());
  if (n >= 0) return {static_cast<std::size_t>(n), false};
  if (errno == EAGAIN || errno == EINTR) return {0, false};
  connected_ = false;
  return {0, true};
}

}  // namespace robuter::hal
