// SPDX-License-Identifier: GPL-3.0-or-later
// A serial port as the configuration names it (device and line words) and its keys' rows, one rule for every section that has one ([links.serial], [ptu]).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "kernel/param.hpp"
#include "kernel/vocabulary.hpp"

namespace robuter::hal {

// The parity bit, with its configuration words ([links.serial] parity, [ptu] parity).
#define ROBUTER_PARITIES(X) X(none, "none") X(even, "even") X(odd, "odd")
enum class Parity : std::uint8_t { ROBUTER_PARITIES(ROBUTER_VOCAB_ENUMERATOR) };
ROBUTER_VOCABULARY(Parity, ROBUTER_PARITIES, "none");
// Flow control, with its configuration words: none, RTS/CTS (hardware), XON/XOFF (software).
#define ROBUTER_FLOW_CONTROLS(X) X(none, "none") X(hardware, "hardware") X(software, "software")
enum class FlowControl : std::uint8_t { ROBUTER_FLOW_CONTROLS(ROBUTER_VOCAB_ENUMERATOR) };
ROBUTER_VOCABULARY(FlowControl, ROBUTER_FLOW_CONTROLS, "none");

// A serial device and how its line is driven, as words checked by the configuration reader
// (hal/linux/serial_settings.hpp turns them into termios bits).
struct SerialPortConfig {
  std::string device;                        // the device, empty = none
  std::uint32_t baud = 9600;                 // line rate, bit/s
  std::string parity = "none";               // a Parity's word: none, even, odd
  std::uint32_t stop_bits = 1;               // 1 or 2
  std::string flow_control = "none";         // a FlowControl's word: none, hardware (RTS/CTS), software (XON/XOFF)
  std::uint32_t retry_ms = 500;              // a lost device is looked for this often, ms
};

// The port's six keys for section struct S (a SerialPortConfig or derived from one): the device
// under `device_key` with its own doc (the section says what is behind it and which option
// overrides it), the line keys with the same names, units, ranges and words everywhere.
template <typename S>
constexpr std::array<param::Param<S>, 6> serial_port_rows(std::string_view device_key, std::string_view device_doc,
                                                          std::string_view baud_doc) {
  using P = param::Param<S>;
  using C = SerialPortConfig;
  return {
      P::text(device_key, static_cast<std::string S::*>(&C::device), "path", device_doc),
      P::integer("baud", static_cast<std::uint32_t S::*>(&C::baud), "bit/s", 1200, 921'600, baud_doc),
      P::word("parity", static_cast<std::string S::*>(&C::parity), word_list<Parity>(), "none, even, odd (docs/HARDWARE.md)"),
      P::integer("stop_bits", static_cast<std::uint32_t S::*>(&C::stop_bits), "", 1, 2, "1 or 2"),
      P::word("flow_control", static_cast<std::string S::*>(&C::flow_control), word_list<FlowControl>(), "none, hardware (RTS/CTS), software (XON/XOFF)"),
      P::integer("retry_ms", static_cast<std::uint32_t S::*>(&C::retry_ms), "ms", 10, 60'000, "a lost device is looked for this often, ms"),
  };
}

}  // namespace robuter::hal
