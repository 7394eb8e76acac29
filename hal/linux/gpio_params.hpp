// SPDX-License-Identifier: GPL-3.0-or-later
// The GPIO inputs' parameters ([hardware.gpio]).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/param.hpp"

namespace robuter {

// Digital inputs on the Linux GPIO character device ([hardware.gpio]; docs/HARDWARE.md).
struct GpioConfig {
  std::string chip;                          // e.g. /dev/gpiochip0; empty = bumpers from the backend
  std::vector<std::uint32_t> bumper_lines;   // line offsets of the bumpers; bit i of `pressed` = entry i
  std::vector<std::uint32_t> input_lines;    // further digital inputs (generic), line offsets
  bool active_low = true;                    // a line reads 0 (low) when its contact is closed
  std::uint32_t debounce_us = 0;             // kernel debounce period, µs (0 = none)
  int line = 0;                              // line of chip in the file, for errors
};

// [hardware.gpio]: each key, its unit, range and doc (the default is the field's initialiser).
std::span<const param::Param<GpioConfig>> gpio_params();

}  // namespace robuter
