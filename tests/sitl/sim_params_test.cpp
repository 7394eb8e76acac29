// SPDX-License-Identifier: GPL-3.0-or-later
// The simulated robot's own parameters ([sim] in the configuration) against what the firmware
// believes: a wheel base 2 % off, a different speed of sound, a mounting error, broken tables.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <unistd.h>

#include "hal/sitl/sim_robot.hpp"
#include "kernel/config.hpp"
#include "modules/firmware/sim_firmware.hpp"

namespace robuter::test {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;  // radians per degree

// An empty 12 × 12 m room with the robot in its middle facing +x, and with `wall` a wall whose
// face is 1.45 m ahead of the front face (walls are 10 cm thick: centre line 1.5 m ahead).
class RoomWorld {
 public:
  explicit RoomWorld(bool wall = false) {
    std::string tmpl = (std::filesystem::temp_directory_path() / "robuter-simparams-XXXXXX").string();
    dir_ = ::mkdtemp(tmpl.data());
    path_ = dir_ + "/room.toml";
    std::ofstream out(path_);
    out << "[world]\nname = \"room\"\nunits = \"m\"\n[start]\nx = 6\ny = 6\nheading_deg = 0\n"
        << "[[wall]]\npoints = [[0, 0], [12, 0], [12, 12], [0, 12]]\nclosed = true\n";
    if (wall) out << "[[wall]]\npoints = [[8.195, 4], [8.195, 8]]\n";
  }
  ~RoomWorld() { std::filesystem::remove_all(dir_); }
  const std::string& path() const { return path_; }

 private:
  std::string dir_, path_;  // private folder and the world file in it
};

Config config_from(const std::string& text) {
  Config cfg;
  const auto err = parse_config(text, "robot.toml", cfg);
  EXPECT_FALSE(err) << (err ? err->message() : "");
  return cfg;
}

// Unwrapped change of heading along a run: adds the wrapped step between two samples.
struct HeadingTrack {
  double last = 0.0, total = 0.0;  // rad
  void add(double theta) {
    total += std::remainder(theta - last, 2.0 * std::numbers::pi);
    last = theta;
  }
};

// Turns on the spot (AM 10 -10: clockwise) until the firmware's odometry has turned `turns` full
// turns, stops, and returns {odometry's turn, the true turn} in degrees.
std::pair<double, double> spin(SimFirmware& fw, double turns) {
  EXPECT_EQ(fw.ask("ASN"), "ack");
  EXPECT_EQ(fw.ask("AM 10 -10"), "ack");
  HeadingTrack odo, truth;
  odo.last = fw.sim().robot().odometry().theta;
  truth.last = fw.sim().robot().pose().theta;
  fw.run_until([&] {
    odo.add(fw.sim().robot().odometry().theta);
    truth.add(fw.sim().robot().pose().theta);
    return -odo.total >= turns * 2.0 * std::numbers::pi;
  }, 200'000);
  EXPECT_EQ(fw.ask("AM 0 0"), "ack");
  fw.run_until([&] {
    odo.add(fw.sim().robot().odometry().theta);
    truth.add(fw.sim().robot().pose().theta);
    const auto& w = fw.sim().robot().wheel_speeds();
    return w.left == 0.0 && w.right == 0.0;
  }, 1000);
  return {-odo.total / kDeg, -truth.total / kDeg};
}

TEST(SimParams, TheSimSectionGivesTheRobotItsOwnWheelBase) {
  RoomWorld world;
  SimFirmware fw(world.path(), config_from("[sim.robot]\nwheel_base = 0.612\n"));
  ASSERT_TRUE(fw.ok()) << fw.error();
  EXPECT_DOUBLE_EQ(fw.sim().robot().params().geometry.wheel_base, 0.612);
  EXPECT_DOUBLE_EQ(fw.sim().robot().params().odometry_wheel_base, 0.600) << "the odometry is the firmware's";
}

// The firmware believes DBW 600 mm; the simulated robot's wheels are 612 mm apart (2 % more).
// The same wheel travel turns the real robot 600/612 of what the odometry says: 360° by
// odometry is 352.9° in truth — 7.06° of heading lost per turn, growing with every turn.
TEST(SimParams, AWheelBaseTwoPercentOffDriftsTheHeading) {
  RoomWorld world;
  SimFirmware exact(world.path());
  SimFirmware off(world.path(), config_from("[sim.robot]\nwheel_base = 0.612\n"));
  ASSERT_TRUE(exact.ok() && off.ok());
  const auto [odo_exact, true_exact] = spin(exact, 1.0);
  const auto [odo_off, true_off] = spin(off, 1.0);
  std::printf("one turn by odometry (deg): matched %.2f true %.2f; 2 %% off %.2f true %.2f (drift %.2f)\n", odo_exact,
              true_exact, odo_off, true_off, odo_off - true_off);
  EXPECT_NEAR(odo_exact - true_exact, 0.0, 0.05) << "matched wheel bases: no drift";
  EXPECT_NEAR(true_off / odo_off, 0.600 / 0.612, 1e-3);
  EXPECT_NEAR(odo_off - true_off, odo_off * (1.0 - 0.600 / 0.612), 0.1);
  // BO reports the firmware's odometry (where it believes it is), not the truth.
  off.run_ticks(20);
  const auto bo = off.ask("BO");
  ASSERT_TRUE(bo);
  int x = 0, y = 0, theta = 0, servo = 0;
  long long clock = 0;
  ASSERT_EQ(std::sscanf(bo->c_str(), "S %d %d %d %d %lld", &x, &y, &theta, &servo, &clock), 5) << *bo;
  EXPECT_NEAR(theta / 100.0, off.sim().robot().odometry().theta / kDeg, 0.02);
  EXPECT_GT(std::abs(theta / 100.0 - off.sim().robot().pose().theta / kDeg), 6.0) << "and the truth is 7° away";
}

// The air's speed of sound 330 m/s while the firmware ranges with 300: every range reads 300/330
// of the truth (a wall 1.45 m ahead of sensor 1 reads 1318 mm).
TEST(SimParams, AFasterSpeedOfSoundShortensTheRanges) {
  RoomWorld world(true);
  SimFirmware exact(world.path());
  SimFirmware fast(world.path(), config_from("[sim.sonar]\nsound_speed = 330\n"));
  ASSERT_TRUE(exact.ok() && fast.ok());
  exact.run_ticks(100);
  fast.run_ticks(100);
  const int true_mm = exact.bb().ranges.reader().peek().mm[0];
  const int read_mm = fast.bb().ranges.reader().peek().mm[0];
  EXPECT_NEAR(true_mm, 1450, 2);
  EXPECT_NEAR(read_mm, 1450.0 * 300.0 / 330.0, 2);
}

// A sensor mounted 30° off its place in the firmware's table sees the wall farther away (its cone
// meets the wall 17.5° off the normal at the nearest: 1450 / cos 17.5° = 1520 mm).
TEST(SimParams, AMountingErrorShowsInTheReadings) {
  RoomWorld world(true);
  SimFirmware fw(world.path(), config_from("[[sim.sonar.sensor]]\nnumber = 1\ndirection_deg = 30\n"));
  ASSERT_TRUE(fw.ok()) << fw.error();
  fw.run_ticks(100);
  const int mm = fw.bb().ranges.reader().peek().mm[0];
  EXPECT_NEAR(mm, 1520, 3) << "the beam meets the wall obliquely, farther than straight ahead";
}

// A broken [sim] table is a start-up error naming the file and the line; nothing runs.
TEST(SimParams, ABrokenSimTableIsAStartUpErrorWithItsLine) {
  RoomWorld world;
  const Config cfg = config_from("[kernel]\ntick_us = 10000\n[sim.robot]\nwheelbase = 0.6\n");
  SimFirmware fw(world.path(), cfg);
  ASSERT_FALSE(fw.ok());
  EXPECT_NE(fw.error().find("robot.toml:4"), std::string::npos) << fw.error();
  EXPECT_NE(fw.error().find("wheelbase"), std::string::npos) << fw.error();
  // A value out of range names its line too (before 2026-12-06 only the file: the [sim] table
  // was copied out of the parsed file, and a toml++ copy drops the source positions).
  const Config neg = config_from("[sim.robot]\nwheel_base = -1\n");
  SimFirmware fw2(world.path(), neg);
  EXPECT_FALSE(fw2.ok());
  EXPECT_NE(fw2.error().find("robot.toml:2"), std::string::npos) << fw2.error();
  const Config wide = config_from("[kernel]\ntick_us = 10000\n\n[sim.sonar]\nhalf_angle_deg = 100\n");
  SimFirmware fw3(world.path(), wide);
  ASSERT_FALSE(fw3.ok());
  EXPECT_NE(fw3.error().find("robot.toml:5"), std::string::npos) << fw3.error();
  EXPECT_NE(fw3.error().find("half_angle_deg"), std::string::npos) << fw3.error();
}

// The options' sonar model comes first, for the ring and the pan-tilt; a configuration's
// [sim.sonar] and [sim.pan_tilt] keys (its `model` too) are the last word (issue #19).
TEST(SimParams, TheSonarModelIsTheOptionsAndTheSimTablesAdjustIt) {
  hal::SimOptions opt;
  EXPECT_EQ(opt.sonar_model, sim::SonarPreset::ideal);  // C++ harnesses: ideal unless they say
  opt.sonar_model = sim::SonarPreset::realistic;
  auto plain = hal::simulated_robot_config(Config{}, opt);
  ASSERT_TRUE(plain);
  EXPECT_TRUE(plain.value().ring.multipath);
  EXPECT_TRUE(plain.value().ring.crosstalk);
  EXPECT_TRUE(plain.value().pan_tilt.spurious_in_window);
  auto adjusted = hal::simulated_robot_config(
      config_from("[sim.sonar]\ncrosstalk = false\n[sim.pan_tilt]\nmodel = \"ideal\"\n"), opt);
  ASSERT_TRUE(adjusted);
  EXPECT_TRUE(adjusted.value().ring.multipath);
  EXPECT_FALSE(adjusted.value().ring.crosstalk);
  EXPECT_FALSE(adjusted.value().pan_tilt.multipath);
  EXPECT_EQ(adjusted.value().pan_tilt.dropout_probability, 0.0);
}

}  // namespace
}  // namespace robuter::test
