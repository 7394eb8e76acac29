// SPDX-License-Identifier: GPL-3.0-or-later
// Simulator configuration overrides from TOML, including rows of the ring layout table.
#include <gtest/gtest.h>

#include "hal/sim/sim_config.hpp"
#include "tests/support/missing_path.hpp"

namespace robuter::sim {
namespace {

TEST(SimConfig, DefaultsAreTheSeedsNumbers) {
  const SimConfig c;
  EXPECT_DOUBLE_EQ(c.robot.geometry.length, 1.025);
  EXPECT_DOUBLE_EQ(c.robot.geometry.width, 0.700);
  EXPECT_DOUBLE_EQ(c.robot.geometry.wheel_base, 0.600);
  EXPECT_DOUBLE_EQ(c.ring.timeout, 0.033);
  EXPECT_DOUBLE_EQ(c.ring.sound_speed, 300.0);
  EXPECT_DOUBLE_EQ(c.pan_tilt.timeout, 0.015);
  EXPECT_DOUBLE_EQ(c.pan_tilt.sound_speed, 335.0);
  EXPECT_DOUBLE_EQ(c.timing.node_delay, 0.030);
}

TEST(SimConfig, OverridesApply) {
  const auto r = parse_sim_config(R"(
[robot]
wheel_base = 0.62
max_accel = 0.8

[odometry]
noise = 0.002
seed = 99

[sonar]
half_angle_deg = 15
timeout_ms = 20
node_delay_ms = 10
noise_sigma = 0.005

[[sonar.sensor]]
number = 7
x = 0.0
direction_deg = -80

[pan_tilt]
x = 0.1
scale = 1.0
offset = 0.0
)",
                                  "sim.toml");
  ASSERT_TRUE(r.ok()) << r.error().describe();
  const SimConfig& c = r.value();
  EXPECT_DOUBLE_EQ(c.robot.geometry.wheel_base, 0.62);
  EXPECT_DOUBLE_EQ(c.robot.limits.max_accel, 0.8);
  EXPECT_DOUBLE_EQ(c.robot.odometry.noise, 0.002);
  EXPECT_EQ(c.robot.odometry.seed, 99u);
  EXPECT_NEAR(c.ring.half_angle, deg_to_rad(15), 1e-15);
  EXPECT_DOUBLE_EQ(c.ring.timeout, 0.020);
  EXPECT_DOUBLE_EQ(c.timing.timeout, 0.020);
  EXPECT_DOUBLE_EQ(c.timing.node_delay, 0.010);
  EXPECT_DOUBLE_EQ(c.layout[6].position.x(), 0.0);
  EXPECT_DOUBLE_EQ(c.layout[6].position.y(), -0.35);  // kept from the default row
  EXPECT_NEAR(c.layout[6].direction, deg_to_rad(-80), 1e-15);
  EXPECT_DOUBLE_EQ(c.pan_tilt_mount.pivot.x(), 0.1);
  EXPECT_DOUBLE_EQ(c.pan_tilt.scale, 1.0);
}

// Expects a configuration error at `line` whose message contains `fragment`.
void expect_sim_config_error(const std::string& text, int line, const std::string& fragment) {
  const auto r = parse_sim_config(text, "sim.toml");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().file, "sim.toml");
  EXPECT_EQ(r.error().line, line) << r.error().describe();
  EXPECT_NE(r.error().message.find(fragment), std::string::npos) << r.error().describe();
}

TEST(SimConfig, ErrorsNameTheLine) {
  expect_sim_config_error("[robot]\nwheelbase = 0.6\n", 2, "[robot]: unknown key 'wheelbase'");
  expect_sim_config_error("[sonar]\ntimeout_ms = \"33\"\n", 2, "timeout_ms: expected a number");
  expect_sim_config_error("[sonar]\nhalf_angle_deg = 95\n", 2, "half_angle_deg: must be within 0..89");
  expect_sim_config_error("[sonar]\n[[sonar.sensor]]\nnumber = 25\n", 3, "number: must be within 1..24");
  expect_sim_config_error("[sonar]\n[[sonar.sensor]]\nx = 0.1\n", 2, "missing key 'number'");
  expect_sim_config_error("[lidar]\nrange = 4\n", 1, "unknown key 'lidar'");
  expect_sim_config_error("[robot]\naxle_to_front = 2.0\n", 1, "axle_to_front must lie within");
}

TEST(SimConfig, MissingFile) {
  const robuter::test::MissingPaths paths;
  const auto r = load_sim_config(paths.missing("sim.toml"));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().line, 0);
}

}  // namespace
}  // namespace robuter::sim
