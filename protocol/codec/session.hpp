// SPDX-License-Identifier: GPL-3.0-or-later
// Per-link session state: the options a client switched on with extensions.
#pragma once

#include <cstdint>
#include <string_view>

namespace robuter::protocol {

// How reply lines end (XL0/XL1/XL2, or set by the serial module's configuration).
enum class Terminator : std::uint8_t {
  cr = 0,    // "\r", the seed's and the default
  lf = 1,    // "\n"
  crlf = 2,  // "\r\n"
};

// Owned by whoever owns the link (one per client); a new session has seed behaviour.
struct SessionState {
  bool verbose_errors = false;             // XB1: `error <code> <reason>` instead of `error`
  bool checksums = false;                  // XC1: every line in and out carries `*HHHH`
  Terminator terminator = Terminator::cr;  // reply line terminator
  std::uint32_t stream_period = 0;         // XS: ticks of 10 ms between status lines, 0 = off
};

// The bytes that end a reply line for a terminator choice.
constexpr std::string_view terminator_bytes(Terminator t) noexcept {
  switch (t) {
    case Terminator::lf: return "\n";
    case Terminator::crlf: return "\r\n";
    case Terminator::cr: break;
  }
  return "\r";
}

}  // namespace robuter::protocol
