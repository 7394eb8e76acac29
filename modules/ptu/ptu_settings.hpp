// SPDX-License-Identifier: GPL-3.0-or-later
// The [ptu] configuration section in the driver's terms.
#pragma once

#include "kernel/config.hpp"
#include "modules/ptu/ptu_driver.hpp"

namespace robuter::ptu {

// Sweep, patience and calibration of the driver from the configuration.
PtuSettings ptu_settings(const PanTiltConfig& c);

}  // namespace robuter::ptu
