// SPDX-License-Identifier: GPL-3.0-or-later
// The GPIO inputs' parameters ([hardware.gpio]): the table (compiled once, not in every includer of the configuration).
#include "hal/linux/gpio_params.hpp"

namespace robuter {

namespace {
constexpr param::Param<GpioConfig> kGpioParams[] = {
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
}  // namespace

std::span<const param::Param<GpioConfig>> gpio_params() { return kGpioParams; }

}  // namespace robuter
