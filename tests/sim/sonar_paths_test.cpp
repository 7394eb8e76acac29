// SPDX-License-Identifier: GPL-3.0-or-later
// The sonar's indirect paths and the named models: multipath by a bounce off a grazing surface,
// cross-talk between transducers fired together, the realistic model's range noise against its
// source, and the models' names in the configuration.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hal/sim/sim_config.hpp"
#include "hal/sim/sonar_presets.hpp"

namespace robuter::sim {
namespace {

// A wall segment from a to b.
Obstacle segment(const char* name, const Vec2& a, const Vec2& b) { return {name, {a, b}, 0}; }

// The sensor at the origin looks along +x. Wall W crosses the axis 1 m ahead with its normal
// 60° off the beam: the least oblique in-cone ray meets it at 47.5°, beyond the 40° at which a
// surface echoes, so the beam bounces off it, to 60° above the axis. Wall S stands across that
// bounced beam 2 m past the bounce: the sound comes back the same way, 1 + 2 m, a reading of 3 m.
// S is outside the sensor's own cone, so without multipath the sensor hears nothing.
// W runs from `w_from` to `w_to` metres along itself from the axis.
World bounce_world(double w_from, double w_to) {
  World w;
  const Vec2 hit(1.0, 0.0);
  const Vec2 along_w(std::cos(deg_to_rad(30.0)), std::sin(deg_to_rad(30.0)));
  w.add_obstacle(segment("W", hit + w_from * along_w, hit + w_to * along_w));
  const Vec2 bounced(std::cos(deg_to_rad(60.0)), std::sin(deg_to_rad(60.0)));
  const Vec2 s_centre = hit + 2.0 * bounced;
  const Vec2 along_s(-bounced.y(), bounced.x());
  w.add_obstacle(segment("S", s_centre - along_s, s_centre + along_s));
  w.finalize();
  return w;
}

TEST(SonarPaths, ABeamBouncedOffAGrazingWallComesBackByTheWallBeyondAsALongReading) {
  const World world = bounce_world(-1.0, 1.0);
  SonarParams p;
  SonarModel model(world, p);
  EXPECT_FALSE(model.trace({0.0, 0.0}, 0.0).found);
  EXPECT_EQ(model.measure_from({0.0, 0.0}, 0.0), p.no_echo);
  p.multipath = true;
  model.set_params(p);
  EXPECT_NEAR(model.measure_from({0.0, 0.0}, 0.0), 3.0, 1e-9);
  // Turned 5°, the bounce still lands on S, square to it no more: S's echo comes back from
  // its normal foot, which the image transducer's cone still holds.
  EXPECT_GT(model.measure_from({0.0, 0.0}, deg_to_rad(5.0)), 2.5);
}

TEST(SonarPaths, NoMultipathWhereTheBouncePointIsOffTheWall) {
  // W only above the axis (from 5 cm on): still in the cone and too oblique to echo, but the
  // path back from S's normal foot would bounce where W is not.
  const World world = bounce_world(0.05, 0.5);
  SonarParams p;
  p.multipath = true;
  SonarModel model(world, p);
  EXPECT_EQ(model.measure_from({0.0, 0.0}, 0.0), p.no_echo);
}

// Borenstein & Koren (1995), fig. 1: sensor y, awaiting its own echo, hears sensor x's sound
// reflected by a wall. x at the origin looks square at a wall 1 m ahead; y, 0.4 m to its right,
// looks 20° to the left of the wall's normal. The surfaces here echo only within 5° of normal
// incidence (a smooth wall), so y hears nothing of its own; x's sound bounces off the wall at
// (1, −0.2), inside both cones, and reaches y after |x' − y| = √(2² + 0.4²) m (x' the image of x).
TEST(SonarPaths, ANodeMatesEchoReachesASensorThatHearsNothingOfItsOwn) {
  World world;
  world.add_obstacle(segment("wall", {1.0, -3.0}, {1.0, 3.0}));
  world.finalize();
  SonarParams p;
  p.max_incidence = deg_to_rad(5.0);
  SonarModel model(world, p);
  const std::vector<SonarMount> node = {{1, {0.0, 0.0}, 0.0}, {2, {0.0, -0.4}, deg_to_rad(20.0)}};
  std::vector<double> out(2);
  model.measure_firing(Pose{}, node, out);
  EXPECT_DOUBLE_EQ(out[0], 1.0);
  EXPECT_EQ(out[1], p.no_echo);  // without cross-talk, y is silent
  p.crosstalk = true;
  model.set_params(p);
  model.measure_firing(Pose{}, node, out);
  EXPECT_DOUBLE_EQ(out[0], 1.0);  // x's own echo comes first
  EXPECT_NEAR(out[1], 0.5 * std::hypot(2.0, 0.4), 1e-12);
  // Fired alone, y hears nothing: the cross-talk is the node-mate's.
  EXPECT_EQ(model.measure(Pose{}, node[1]), p.no_echo);
  // Turned 20° further, the bounce point leaves y's cone: silent again.
  const std::vector<SonarMount> away = {node[0], {2, {0.0, -0.4}, deg_to_rad(40.0)}};
  model.measure_firing(Pose{}, away, out);
  EXPECT_EQ(out[1], p.no_echo);
}

// The Polaroid 6500 ranging module's specified accuracy, ±1 % of the reading, is the realistic
// model's range noise at two standard deviations: of the echoes of a wall square to the beam,
// 95 % fall within ±1 % (drop-outs and noise pulses, which are other effects, set aside).
TEST(SonarPaths, TheRealisticModelsRangeNoiseIsThePolaroidModulesOnePercent) {
  for (const double d : {0.5, 1.0, 2.0, 4.0}) {
    World world;
    world.add_obstacle(segment("wall", {d, -3.0}, {d, 3.0}));
    world.finalize();
    SonarParams p;
    apply_sonar_preset(SonarPreset::realistic, p);
    SonarModel model(world, p);
    Rng rng(11);
    int echoes = 0, within = 0;
    for (int i = 0; i < 20000; ++i) {
      const double r = model.measure_from({0.0, 0.0}, 0.0, &rng);
      if (r == p.no_echo || std::abs(r - d) > 0.05 * d) continue;  // a drop-out or a noise pulse
      ++echoes;
      if (std::abs(r - d) <= 0.01 * d) ++within;
    }
    const double share = static_cast<double>(within) / echoes;
    EXPECT_NEAR(share, 0.954, 0.01) << d << " m";
    EXPECT_GT(echoes, 19000) << d << " m";
  }
}

// A noise pulse at a uniform time of the listening window is heard only when it comes before
// the echo: near a wall few are, in the open every one is.
TEST(SonarPaths, ANoisePulseIsHeardOnlyBeforeTheEcho) {
  World world;
  world.add_obstacle(segment("wall", {0.5, -3.0}, {0.5, 3.0}));
  world.finalize();
  SonarParams p;
  p.spurious_probability = 1.0;
  p.spurious_in_window = true;
  SonarModel model(world, p);
  Rng rng(3);
  int short_ones = 0;
  for (int i = 0; i < 10000; ++i) {
    const double r = model.measure_from({0.0, 0.0}, 0.0, &rng);
    ASSERT_GE(r, p.min_range);
    ASSERT_LE(r, 0.5);
    if (r < 0.5) ++short_ones;
  }
  // (0.5 − 0.15) / (4.95 − 0.15) of the pulses come before the echo.
  EXPECT_NEAR(short_ones / 10000.0, 0.35 / 4.8, 0.01);
  int heard = 0;
  for (int i = 0; i < 1000; ++i) heard += model.measure_from({0.0, 0.0}, kPi, &rng) != p.no_echo;
  EXPECT_EQ(heard, 1000);
}

TEST(SonarPaths, TheModelIsNamedInTheConfigurationAndItsKeysStillApply) {
  auto c = parse_sim_config("[sonar]\nmodel = \"realistic\"\ndropout_probability = 0.0\n[pan_tilt]\nmodel = \"stress\"\n", "t.toml");
  ASSERT_TRUE(c) << c.error().describe();
  EXPECT_TRUE(c.value().ring.multipath);
  EXPECT_TRUE(c.value().ring.crosstalk);
  EXPECT_DOUBLE_EQ(c.value().ring.noise_relative, kRealisticNoiseRelative);
  EXPECT_DOUBLE_EQ(c.value().ring.dropout_probability, 0.0);
  EXPECT_DOUBLE_EQ(c.value().pan_tilt.spurious_probability, 0.002);
  EXPECT_FALSE(c.value().pan_tilt.multipath);
  auto bad = parse_sim_config("[sonar]\nmodel = \"perfect\"\n", "t.toml");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().describe().find("model"), std::string::npos);
  for (const char* name : {"ideal", "stress", "realistic"}) {
    ASSERT_TRUE(sonar_preset(name));
    EXPECT_EQ(sonar_preset_name(*sonar_preset(name)), name);
  }
  EXPECT_FALSE(sonar_preset("Realistic"));
}

}  // namespace
}  // namespace robuter::sim
