// SPDX-License-Identifier: GPL-3.0-or-later
// Standard input/output made non-blocking.
#include "hal/link/stdio_link.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>

namespace robuter::hal {

StdioLink::StdioLink() {
  in_fd_ = STDIN_FILENO;
  out_fd_ = STDOUT_FILENO;
  fcntl(in_fd_, F_SETFL, fcntl(in_fd_, F_GETFL) | O_NONBLOCK);
  fcntl(out_fd_, F_SETFL, fcntl(out_fd_, F_GETFL) | O_NONBLOCK);
  connected_ = true;
}

IoResult StdioLink::write(std::span<const std::uint8_t> in) {
  if (out_fd_ < 0) return {0, true};
  const ssize_t n = ::write(out_fd_, in.data(), in.size());
  if (n >= 0) return {static_cast<std::size_t>(n), false};
  if (errno == EAGAIN || errno == EINTR) return {0, false};
  out_fd_ = -1;  // standard output is gone (EPIPE): nothing more can be written
  connected_ = false;
  return {0, true};
}

}  // namespace robuter::hal
