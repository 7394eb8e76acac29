// SPDX-License-Identifier: GPL-3.0-or-later
// Channel 7 of the SITL ring: the pan-tilt's two sonars, fired at the emulated unit's angle,
// against hand-computed ranges in a walled box; timing, masks, and the built-in sweep.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <unistd.h>

#include "hal/sim/sonar_layout.hpp"
#include "hal/sitl/ptu_sweep.hpp"
#include "hal/sitl/sim_robot.hpp"

namespace robuter::hal {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;  // radians per degree

// A 4 × 4 m box of 10 cm walls (inner faces at 0.05 and 3.95 m) with the robot at (x, y, heading).
std::string box_world(double x, double y, double heading_deg) {
  static int n = 0;
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("robuter-sitl-box-" + std::to_string(::getpid()) + "-" + std::to_string(n++) + ".toml"))
                               .string();
  std::ofstream(path) << "[world]\nname = \"box\"\nunits = \"m\"\n"
                      << "[start]\nx = " << x << "\ny = " << y << "\nheading_deg = " << heading_deg << "\n"
                      << "[[wall]]\npoints = [[0, 0], [4, 0], [4, 4], [0, 4]]\nclosed = true\n";
  return path;
}

// The seed's calibration line: a real range r (m) is reported as 0.96 r + 43 mm.
std::uint16_t reported_mm(double real_m) { return static_cast<std::uint16_t>(std::lround((0.96 * real_m + 0.043) * 1000.0)); }

// A SimRobot in the box, its pan-tilt at `position`.
struct Box {
  std::string file;
  std::optional<SimRobot> robot;
  Box(double x, double y, double heading_deg, std::int32_t position = 0) : file(box_world(x, y, heading_deg)) {
    SimOptions opt;
    opt.world_file = file;
    opt.ptu.start_position = position;
    robot.emplace(Config{}, opt);
  }
  ~Box() { std::filesystem::remove(file); }
};

// Fires channel 7 now and reads it 15 ms later.
NodeRanges fire_and_read(SimRobot& r, std::uint8_t mask = 0x3) {
  NodeRanges out{};
  EXPECT_TRUE(r.ring().fire(kPanTiltChannel, mask));
  r.advance_to(r.time() + 0.015);
  EXPECT_TRUE(r.ring().read(kPanTiltChannel, out));
  return out;
}

// Pan angle 0, robot heading east at (2.0, 1.5): index 1 looks along +90° (north), index 0
// south. The pivot is 30 mm behind the axle, each transducer 50 mm from it: north face at
// y = 1.55 m → 2.40 m to the wall at 3.95; south face at y = 1.45 → 1.40 m to the wall at 0.05.
TEST(PanTiltChannel, RangesInABoxAtPanZero) {
  Box box(2.0, 1.5, 0.0);
  ASSERT_FALSE(box.robot->error()) << *box.robot->error();
  const NodeRanges out = fire_and_read(*box.robot);
  EXPECT_EQ(out[1], reported_mm(2.40));  // 2347
  EXPECT_EQ(out[0], reported_mm(1.40));  // 1387
  EXPECT_EQ(out[1], 2347);
  EXPECT_EQ(out[0], 1387);
  EXPECT_EQ(out[2], 0);
  EXPECT_EQ(out[3], 0);
}

// Heading north at (1.5, 1.5): index 1 looks west from x = 1.45 (1.40 m), index 0 east from
// x = 1.55 (2.40 m).
TEST(PanTiltChannel, RangesFollowTheRobotHeading) {
  Box box(1.5, 1.5, 90.0);
  const NodeRanges out = fire_and_read(*box.robot);
  EXPECT_EQ(out[1], reported_mm(1.40));
  EXPECT_EQ(out[0], reported_mm(2.40));
}

// Beyond 15 ms × 335 m/s / 2 = 2.51 m nothing returns: 0, the HAL's "no echo".
TEST(PanTiltChannel, NoEchoBeyondTheTimeOutRange) {
  Box box(2.0, 1.0, 0.0);
  const NodeRanges out = fire_and_read(*box.robot);
  EXPECT_EQ(out[1], 0);                  // 2.90 m to the north wall
  EXPECT_EQ(out[0], reported_mm(0.90));  // 0.90 m to the south wall
}

// Pan position 1440 = 74°: the beams look along 164° and −16°; the readings are the sonar
// model's at exactly that direction.
TEST(PanTiltChannel, RangesFollowThePanAngle) {
  Box box(2.0, 2.0, 0.0, 1440);
  SimRobot& r = *box.robot;
  EXPECT_DOUBLE_EQ(r.ptu().angle_deg(), 74.0);
  sim::SonarModel model(r.world(), sim::default_pan_tilt_params());
  const sim::PanTiltReading m =
      sim::measure_pan_tilt(model, r.robot().pose(), sim::PanTiltMount{}, (74.0 + 90.0) * kDeg);
  const NodeRanges out = fire_and_read(r);
  EXPECT_EQ(out[1], std::lround(m.facing * 1000.0));
  EXPECT_EQ(out[0], std::lround(m.opposite * 1000.0));
  // West wall: 16° off its normal, 4° outside the cone, so the echo is at the cone edge.
  const double west = (2.0 - 0.03 + 0.05 * std::cos(164.0 * kDeg) - 0.05) / std::cos(3.5 * kDeg);
  EXPECT_EQ(out[1], reported_mm(west));
}

TEST(PanTiltChannel, ResultsAreReadyAfterFifteenMillisecondsOnce) {
  Box box(2.0, 1.5, 0.0);
  SimRobot& r = *box.robot;
  r.ring().configure(10, 300);  // the ring's settings do not touch the pan-tilt's
  NodeRanges out{};
  EXPECT_FALSE(r.ring().read(kPanTiltChannel, out));  // never fired
  ASSERT_TRUE(r.ring().fire(kPanTiltChannel, 0x3));
  r.advance_to(0.014);
  EXPECT_FALSE(r.ring().read(kPanTiltChannel, out));
  r.advance_to(0.015);
  EXPECT_TRUE(r.ring().read(kPanTiltChannel, out));
  EXPECT_EQ(out[1], 2347);
  EXPECT_FALSE(r.ring().read(kPanTiltChannel, out));  // taken
  EXPECT_TRUE(r.last_pan_tilt().valid);
  EXPECT_EQ(r.last_pan_tilt().mm[0], 1387);
}

TEST(PanTiltChannel, MaskSelectsTheSensorsAndOtherChannelsAreAbsent) {
  Box box(2.0, 1.5, 0.0);
  SimRobot& r = *box.robot;
  EXPECT_FALSE(r.ring().fire(kPanTiltChannel, 0x4));  // only two sonars on the pan-tilt
  EXPECT_FALSE(r.ring().fire(6, 0x1));
  EXPECT_FALSE(r.ring().fire(8, 0x1));
  NodeRanges out = fire_and_read(r, 0x1);
  EXPECT_EQ(out[0], 1387);
  EXPECT_EQ(out[1], 0);
  out = fire_and_read(r, 0x2);
  EXPECT_EQ(out[0], 0);
  EXPECT_EQ(out[1], 2347);
}

// The built-in sweep (robuterd --ptu-sweep): end to end and back, a firing near every 5° mark.
TEST(PanTiltChannel, BuiltInSweepTurnsAtTheLimitsAndFires) {
  Box box(2.0, 2.0, 0.0);
  SimRobot& r = *box.robot;
  PtuSweep sweep(r);
  int at_max = 0, at_min = 0;
  for (int i = 1; i <= 800; ++i) {  // 8 s in 10 ms ticks
    r.advance_to(i * 0.01);
    sweep.run();
    at_max += r.ptu().position() == 1655;
    at_min += r.ptu().position() == -1755;
  }
  EXPECT_GT(at_max, 0);
  EXPECT_GT(at_min, 0);
  EXPECT_GE(sweep.turns(), 3u);  // -1755 (start), 1655, -1755, ...
  // 36 marks per 175° pass, about 3 passes; the 30 ms cadence misses a few marks.
  EXPECT_GT(sweep.firings(), 60u);
  EXPECT_GE(sweep.readings() + 1, sweep.firings());
  EXPECT_TRUE(r.last_pan_tilt().valid);
  const double a = r.last_pan_tilt().angle_deg;
  EXPECT_LE(std::abs(a - 5.0 * std::round(a / 5.0)), 1.0);
}

}  // namespace
}  // namespace robuter::hal
