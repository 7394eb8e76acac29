// SPDX-License-Identifier: GPL-3.0-or-later
// Parsing of the serial configuration words and the termios bits they stand for.
#include "hal/linux/serial_settings.hpp"

#include <array>
#include <utility>

namespace robuter::hal {

namespace {
constexpr std::array<std::pair<unsigned, speed_t>, 11> kRates{{
    {1200, B1200}, {2400, B2400}, {4800, B4800}, {9600, B9600}, {19200, B19200}, {38400, B38400},
    {57600, B57600}, {115200, B115200}, {230400, B230400}, {460800, B460800}, {921600, B921600},
}};

// The termios rate of `baud`; null when it has none.
const speed_t* rate_of(unsigned baud) {
  for (const auto& [b, r] : kRates)
    if (b == baud) return &r;
  return nullptr;
}
}  // namespace

bool valid_baud(unsigned baud) { return rate_of(baud) != nullptr; }


// Why VMIN 1: with VMIN 0 and VTIME 0 Linux returns 0 from an idle non-blocking read, which
// would look like the device hanging up.
bool encode_termios(const SerialSettings& s, termios& t) {
  const speed_t* rate = rate_of(s.baud);
  if (rate == nullptr) return false;
  cfmakeraw(&t);
  cfsetispeed(&t, *rate);
  cfsetospeed(&t, *rate);
  t.c_cflag |= CLOCAL | CREAD | CS8;
  t.c_cflag &= ~static_cast<tcflag_t>(PARENB | PARODD | CSTOPB | CRTSCTS);
  t.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY | INPCK);
  if (s.parity != Parity::none) {
    t.c_cflag |= PARENB;
    if (s.parity == Parity::odd) t.c_cflag |= PARODD;
    t.c_iflag |= INPCK | IGNPAR;  // a byte with a parity error is dropped
  }
  if (s.stop_bits == 2) t.c_cflag |= CSTOPB;
  if (s.flow == FlowControl::hardware) t.c_cflag |= CRTSCTS;
  if (s.flow == FlowControl::software) t.c_iflag |= IXON | IXOFF;
  t.c_cc[VMIN] = 1;
  t.c_cc[VTIME] = 0;
  return true;
}

}  // namespace robuter::hal
