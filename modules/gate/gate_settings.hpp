// SPDX-License-Identifier: GPL-3.0-or-later
// The [gate], [ptu] and [doors] configuration in the passage finder's terms.
#pragma once

#include "kernel/config.hpp"
#include "modules/gate/gate_logic.hpp"

namespace robuter::gate {

GateSettings gate_settings(const Config& c);

}  // namespace robuter::gate
