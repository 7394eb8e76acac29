// SPDX-License-Identifier: GPL-3.0-or-later
// Serial line settings (rate, parity, stop bits, flow control) and their termios encoding.
#pragma once

#include <termios.h>

#include <cstdint>
#include <string_view>

#include "hal/api/serial_port_params.hpp"

namespace robuter::hal {


// How one serial port is driven; always 8 data bits, raw (no line editing, no translation).
struct SerialSettings {
  unsigned baud = 9600;                   // line rate, bit/s (one of supported_bauds())
  Parity parity = Parity::none;           // parity bit
  unsigned stop_bits = 1;                 // 1 or 2
  FlowControl flow = FlowControl::none;   // none, RTS/CTS (hardware) or XON/XOFF (software)
  unsigned retry_ms = 500;                // a lost device is looked for this often, ms
};

// True when `baud` is a rate this HAL can set (standard termios rates 1200…921600).
bool valid_baud(unsigned baud);
// Writes `s` into `t`: raw 8-bit, receiver on, modem lines ignored (CLOCAL), VMIN 1/VTIME 0 so a
// non-blocking read says EAGAIN when idle and 0 only on hang-up. False if the rate is unknown.
bool encode_termios(const SerialSettings& s, termios& t);

}  // namespace robuter::hal
