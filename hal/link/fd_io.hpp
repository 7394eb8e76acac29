// SPDX-License-Identifier: GPL-3.0-or-later
// One reading of a non-blocking read(2) or write(2)'s return for every descriptor stream (pty, stdio, serial).
#pragma once

#include <sys/types.h>

#include <cerrno>
#include <cstddef>

#include "hal/api/byte_stream.hpp"

namespace robuter::hal {

// Which call returned.
enum class FdCall : bool { read, write };

// The IoResult of a `call` that returned `n`, with errno as the call left it: the bytes moved;
// nothing for now on EAGAIN or EINTR; else the descriptor is lost: `lose(why)` is called, `why`
// being errno, or EPIPE for a read's end of file (the peer hung up).
template <class Lose>
IoResult fd_io_result(FdCall call, ssize_t n, Lose&& lose) {
  if (n > 0 || (n == 0 && call == FdCall::write)) return {static_cast<std::size_t>(n), false};
  if (n < 0 && (errno == EAGAIN || errno == EINTR)) return {0, false};
  lose(n == 0 ? EPIPE : errno);
  return {0, true};
}

}  // namespace robuter::hal
