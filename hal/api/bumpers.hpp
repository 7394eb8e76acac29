// SPDX-License-Identifier: GPL-3.0-or-later
// HAL: contact bumpers.
#pragma once

#include <cstdint>

namespace robuter::hal {

class Bumpers {
 public:
  virtual ~Bumpers() = default;
  // Bit i set = bumper i pressed; 0 = no contact.
  virtual std::uint32_t pressed() const = 0;
};

}  // namespace robuter::hal
