// SPDX-License-Identifier: GPL-3.0-or-later
// HAL: generic digital inputs (switches, contacts) read as one bit mask.
#pragma once

#include <cstddef>
#include <cstdint>

namespace robuter::hal {

class DigitalInputs {
 public:
  virtual ~DigitalInputs() = default;
  // Bit i set = input i active (after active-low inversion); an input that was active at any
  // moment since the last call reads active once, so a short pulse is not missed.
  virtual std::uint32_t levels() const = 0;
  // Inputs available (bits used in levels()).
  virtual std::size_t count() const = 0;
};

}  // namespace robuter::hal
