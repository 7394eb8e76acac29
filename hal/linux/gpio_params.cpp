// SPDX-License-Identifier: GPL-3.0-or-later
// The GPIO inputs' parameters ([hardware.gpio]): the table (compiled once, not in every includer of the configuration).
#include "hal/linux/gpio_params.hpp"

namespace robuter {

std::span<const param::Param<GpioConfig>> gpio_params() {
  using P = param::Param<GpioConfig>;
  static constexpr P kRows[] = {
      P::text("chip", &GpioConfig::chip, "path", "e.g. /dev/gpiochip0; empty = bumpers from the backend"),
      P::integer("bumper_lines", &GpioConfig::bumper_lines, "offsets", 0, 1023, "line offsets of the bumpers; bit i of `pressed` = entry i"),
      P::integer("input_lines", &GpioConfig::input_lines, "offsets", 0, 1023, "further digital inputs (generic), line offsets"),
      P::flag("active_low", &GpioConfig::active_low, "a line reads 0 (low) when its contact is closed"),
      P::integer("debounce_us", &GpioConfig::debounce_us, "µs", 0, 1'000'000, "kernel debounce period, µs (0 = none)"),
  };
  return kRows;
}

}  // namespace robuter
