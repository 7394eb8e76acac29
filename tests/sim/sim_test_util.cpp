// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers shared by the simulator tests.
#include "tests/sim/sim_test_util.hpp"

namespace robuter::sim::test {

// Obstacles named "obstacle N", source "<test>".
World make_world(const std::vector<std::vector<Vec2>>& polygons) {
  World w;
  w.source = "<test>";
  int i = 0;
  for (const auto& p : polygons) w.add_obstacle({"obstacle " + std::to_string(++i), p, 0});
  w.finalize();
  return w;
}

// Counter-clockwise from the lower-left corner.
std::vector<Vec2> rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// The worlds folder and the test output folder come from the build (compile definitions).
std::string world_path(const std::string& name) { return std::string(ROBUTER_WORLDS_DIR) + "/" + name; }

std::string out_path(const std::string& name) { return std::string(ROBUTER_SIM_TEST_OUT) + "/" + name; }

}  // namespace robuter::sim::test
