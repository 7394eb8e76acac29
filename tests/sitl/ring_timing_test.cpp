// SPDX-License-Identifier: GPL-3.0-or-later
// The SITL ring's timing: a node measures when it fires and reports once its echoes are in, or at the firing's time-out.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <unistd.h>

#include "hal/sitl/sim_robot.hpp"

namespace robuter::hal {
namespace {

// The robot's axle at (2, 2) m heading east in a 4 × 4 m box of 10 cm walls: sensor 1 (on the
// front face, 695 mm ahead of the axle) is 1255 mm from the east wall's inner face (3.95 m).
struct BoxedRobot {
  std::string file;
  std::optional<SimRobot> robot;
  BoxedRobot() {
    file = (std::filesystem::temp_directory_path() / ("robuter-sitl-ring-" + std::to_string(::getpid()) + ".toml")).string();
    std::ofstream(file) << "[world]\nname = \"box\"\nunits = \"m\"\n[start]\nx = 2.0\ny = 2.0\nheading_deg = 0.0\n"
                        << "[[wall]]\npoints = [[0, 0], [4, 0], [4, 4], [0, 4]]\nclosed = true\n";
    SimOptions opt;
    opt.world_file = file;
    robot.emplace(Config{}, opt);
  }
  ~BoxedRobot() { std::filesystem::remove(file); }
};

constexpr double kEcho = 2.0 * 1.255 / 300.0;  // sensor 1's round trip, s (8.37 ms)

TEST(SimRing, ANodeReportsOnceItsEchoesAreIn) {
  BoxedRobot b;
  ASSERT_FALSE(b.robot->error()) << *b.robot->error();
  SimRobot& r = *b.robot;
  const double t0 = r.time();
  ASSERT_TRUE(r.ring().fire(0, 0x1));
  NodeRanges mm{};
  r.advance_to(t0 + kEcho - 0.0002);
  EXPECT_FALSE(r.ring().read(0, mm)) << "the echo is not back yet";
  r.advance_to(t0 + kEcho + 0.0002);
  ASSERT_TRUE(r.ring().read(0, mm)) << "back after 8.4 ms, long before the 33 ms time-out";
  EXPECT_EQ(mm[0], 1255);
  EXPECT_EQ(mm[1], 0) << "not fired";
}

TEST(SimRing, ANodeMeasuresWhereTheRobotWasWhenItFired) {
  BoxedRobot b;
  SimRobot& r = *b.robot;
  const double t0 = r.time();
  ASSERT_TRUE(r.ring().fire(0, 0x1));
  r.robot().place(sim::Pose{2.5, 2.0, 0.0});  // half a metre closer before the read
  r.advance_to(t0 + 0.033);
  NodeRanges mm{};
  ASSERT_TRUE(r.ring().read(0, mm));
  EXPECT_EQ(mm[0], 1255);
}

TEST(SimRing, AShortenedFiringHearsOnlyItsReachAndReportsAtItsTimeOut) {
  BoxedRobot b;
  SimRobot& r = *b.robot;
  const double t0 = r.time();
  ASSERT_TRUE(r.ring().fire(0, 0x1, 5));  // 5 ms: 750 mm at 300 m/s, the wall is at 1255 mm
  NodeRanges mm{};
  r.advance_to(t0 + 0.0049);
  EXPECT_FALSE(r.ring().read(0, mm));
  r.advance_to(t0 + 0.0051);
  ASSERT_TRUE(r.ring().read(0, mm)) << "nothing within reach: reported at the firing's time-out";
  EXPECT_EQ(mm[0], 0);
  // A time-out longer than the configured 33 ms is capped by it.
  ASSERT_TRUE(r.ring().fire(0, 0x1, 100));
  r.advance_to(r.time() + kEcho + 0.0002);
  ASSERT_TRUE(r.ring().read(0, mm));
  EXPECT_EQ(mm[0], 1255);
}

}  // namespace
}  // namespace robuter::hal
