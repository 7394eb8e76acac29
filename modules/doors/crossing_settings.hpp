// SPDX-License-Identifier: GPL-3.0-or-later
// The [doors], [ptu] and [robot] configuration in the door crossing's terms.
#pragma once

#include "kernel/config.hpp"
#include "modules/doors/crossing.hpp"

namespace robuter::doors {

CrossingSettings crossing_settings(const Config& c);

}  // namespace robuter::doors
