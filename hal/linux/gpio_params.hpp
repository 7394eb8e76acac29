// SPDX-License-Identifier: GPL-3.0-or-later
// The GPIO inputs' parameters ([hardware.gpio]).
#pragma once

#include <cstdint>
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
inline constexpr param::Param<GpioConfig> kGpioParams[] = {
    {"chip", &GpioConfig::chip, "path", 0, 0, "",
     "e.g. /dev/gpiochip0; empty = bumpers from the backend"},
    {"bumper_lines", &GpioConfig::bumper_lines, "offsets", 0, 1023, "",
     "line offsets of the bumpers; bit i of `pressed` = entry i"},
    {"input_lines", &GpioConfig::input_lines, "offsets", 0, 1023, "",
     "further digital inputs (generic), line offsets"},
    {"active_low", &GpioConfig::active_low, "bool", 0, 0, "",
     "a line reads 0 (low) when its contact is closed"},
    {"debounce_us", &GpioConfig::debounce_us, "µs", 0, 1'000'000, "",
     "kernel debounce period, µs (0 = none)"},
};

}  // namespace robuter
