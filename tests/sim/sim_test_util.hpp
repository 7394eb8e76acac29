// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers shared by the simulator tests: small worlds built in code, and the worlds folder.
#pragma once

#include <string>
#include <vector>

#include "hal/sim/world.hpp"

namespace robuter::sim::test {

// A world made of the given polygons (finalised).
World make_world(const std::vector<std::vector<Vec2>>& polygons);

// An axis-aligned rectangle polygon.
std::vector<Vec2> rect(double x0, double y0, double x1, double y1);

// Path of a shipped world file.
std::string world_path(const std::string& name);

// Path for a test output file in the build tree.
std::string out_path(const std::string& name);

}  // namespace robuter::sim::test
