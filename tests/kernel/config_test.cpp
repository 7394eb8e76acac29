// SPDX-License-Identifier: GPL-3.0-or-later
// Configuration parsing: defaults equal the seed's constants; each bad file gives one clear error.
#include <gtest/gtest.h>

#include "kernel/config.hpp"
#include "tests/support/missing_path.hpp"

namespace robuter {
namespace {

// Parses `text` and returns the error message, or "" when it is accepted.
std::string error_of(const std::string& text, Config* out = nullptr) {
  Config c;
  const auto err = parse_config(text, "robot.toml", c);
  if (out) *out = c;
  return err ? err->message() : "";
}

TEST(Config, DefaultsAreTheSeedConstants) {
  Config c;
  EXPECT_EQ(c.kernel.tick_us, 10'000u);
  EXPECT_EQ(c.robot.length_mm, 1025u);
  EXPECT_EQ(c.robot.width_mm, 700u);
  EXPECT_EQ(c.robot.wheel_base_mm, 600u);
  EXPECT_EQ(c.sonar.node_delay_ticks, 3u);
  EXPECT_EQ(c.sonar.timeout_ms, 33u);
  EXPECT_EQ(c.sonar.sound_speed_m_s, 300u);
  EXPECT_EQ(c.emergency.mask, 7u);
  EXPECT_EQ(c.emergency.comm_limit_ticks, 18'000u);
  EXPECT_EQ(c.emergency.min_safety_mm, 220u);
  EXPECT_FALSE(c.permissions.pass_through);
}

TEST(Config, AcceptsAFullFile) {
  Config c;
  const auto err = error_of(R"(
[kernel]
tick_us = 5000
realtime = true
rt_priority = 80
log_level = "debug"
[robot]
wheel_base_mm = 610
[emergency]
mask = 3
[permissions]
pass_through = true
pass_through_allow = ["TSYS"]
[modules]
enabled = ["heartbeat"]
[process.heartbeat]
period = 50
budget_us = 200
)", &c);
  ASSERT_EQ(err, "");
  EXPECT_EQ(c.kernel.tick_us, 5000u);
  EXPECT_TRUE(c.kernel.realtime);
  EXPECT_EQ(c.kernel.rt_priority, 80);
  EXPECT_EQ(c.robot.wheel_base_mm, 610u);
  EXPECT_EQ(c.emergency.mask, 3u);
  ASSERT_EQ(c.permissions.pass_through_allow.size(), 1u);
  ASSERT_TRUE(c.enabled_modules);
  ASSERT_EQ(c.processes.size(), 1u);
  EXPECT_EQ(c.processes[0].name, "heartbeat");
  EXPECT_EQ(c.processes[0].period, 50u);
  EXPECT_FALSE(c.processes[0].offset);
  EXPECT_EQ(c.processes[0].line, 16);
}

TEST(Config, UnknownKeyNamesFileLineAndKey) {
  EXPECT_EQ(error_of("[kernel]\ntick_us = 10000\ntik_us = 5\n"), "robot.toml:3: key 'kernel.tik_us': unknown key");
  EXPECT_EQ(error_of("[kernal]\n"), "robot.toml:1: key 'kernal': unknown key");
}

TEST(Config, WrongTypeIsNamed) {
  EXPECT_EQ(error_of("[kernel]\ntick_us = \"10\"\n"),
            "robot.toml:2: key 'kernel.tick_us': expected an integer, got a string");
  EXPECT_EQ(error_of("[emergency]\nlatch = 1\n"), "robot.toml:2: key 'emergency.latch': expected true or false, got an integer");
  EXPECT_EQ(error_of("kernel = 3\n"), "robot.toml:1: key 'kernel': expected a table, got an integer");
}

TEST(Config, OutOfRangeValueIsNamed) {
  EXPECT_EQ(error_of("[kernel]\ntick_us = 0\n"), "robot.toml:2: key 'kernel.tick_us': 0 is out of range 100..1000000");
  EXPECT_EQ(error_of("[emergency]\nmask = 9\n"), "robot.toml:2: key 'emergency.mask': 9 is out of range 0..7");
  EXPECT_EQ(error_of("[kernel]\nlog_level = \"loud\"\n"),
            "robot.toml:2: key 'kernel.log_level': 'loud' is not one of: debug, info, warn, error, off");
  EXPECT_EQ(error_of("[sonar]\nschedule = \"fast\"\n"), "robot.toml:2: key 'sonar.schedule': 'fast' is not one of: watch, seed");
  EXPECT_EQ(error_of("[sonar]\nmoving_timeout_ms = 2000\n"),
            "robot.toml:2: key 'sonar.moving_timeout_ms': 2000 is out of range 0..1000");
}

// The localisation's particle counts are bounded at the 2,000 whose activations were measured: a
// step's motion and resampling run whole in one activation (docs/LOCALISATION.md, "The module").
TEST(Config, TheLocalisationsParticlesAreBoundedAtWhatWasMeasured) {
  EXPECT_EQ(error_of("[localise]\nmax_particles = 2000\n"), "");
  EXPECT_EQ(error_of("[localise]\nmax_particles = 2001\n"),
            "robot.toml:2: key 'localise.max_particles': 2001 is out of range 10..2000");
  EXPECT_EQ(error_of("[localise]\nparticles_per_run = 100000\n"),
            "robot.toml:2: key 'localise.particles_per_run': 100000 is out of range 10..300");
  EXPECT_EQ(error_of("[localise]\nmin_particles = 5\n"), "robot.toml:2: key 'localise.min_particles': 5 is out of range 10..2000");
}

// Why: an activation's work is bounded by particles_per_run and traces_per_run, capped where the
// longest activation was measured under 2 ms (a global search, tracking): particles_per_run = 2000
// took 2.7 ms an activation with the traces bounded, traces_per_run = 100 2.2 ms.
TEST(Config, TheLocalisationsWorkPerActivationIsBoundedAtWhatWasMeasured) {
  EXPECT_EQ(error_of("[localise]\nparticles_per_run = 300\ntraces_per_run = 80\n"), "");
  EXPECT_EQ(error_of("[localise]\nparticles_per_run = 2000\n"),
            "robot.toml:2: key 'localise.particles_per_run': 2000 is out of range 10..300");
  EXPECT_EQ(error_of("[localise]\ntraces_per_run = 81\n"), "robot.toml:2: key 'localise.traces_per_run': 81 is out of range 10..80");
  EXPECT_EQ(error_of("[localise]\ntraces_per_run = 0\n"), "robot.toml:2: key 'localise.traces_per_run': 0 is out of range 10..80");
}

// The planner's map limits (docs/CONFIG.md): 512 x 512 cells for the rectangle, 1 M for a disc.
TEST(Config, APlannerMapTooLargeIsRefusedOnItsWidth) {
  EXPECT_EQ(error_of("[planner]\nmap_width_mm = 25600\nmap_height_mm = 25600\n"), "");
  const std::string e = error_of("[planner]\nmap_width_mm = 26000\nmap_height_mm = 26000\n");
  EXPECT_NE(e.find("key 'planner.map_width_mm'"), std::string::npos) << e;
  EXPECT_NE(e.find("a map of 270400 cells is too large for the rectangle planner (at most 262144)"), std::string::npos) << e;
  EXPECT_EQ(error_of("[planner]\nfootprint = \"disc\"\nmap_width_mm = 50000\nmap_height_mm = 50000\n"), "");
}

TEST(Config, SyntaxErrorGivesTheLine) {
  const auto e = error_of("[kernel]\ntick_us = = 3\n");
  EXPECT_EQ(e.rfind("robot.toml:2: ", 0), 0u) << e;
}

TEST(Config, MissingFileIsClear) {
  Config c;
  const robuter::test::MissingPaths paths;
  const std::string file = paths.missing("robot.toml");
  const auto err = load_config(file, c);
  ASSERT_TRUE(err);
  EXPECT_EQ(err->message(), file + ": cannot open: No such file or directory");
}

TEST(Config, ShippedDefaultFileParsesToTheDefaults) {
  Config c;
  const auto err = load_config(ROBUTER_SOURCE_DIR "/config/robuterd.toml", c);
  ASSERT_FALSE(err) << err->message();
  Config d;
  EXPECT_EQ(c.kernel.tick_us, d.kernel.tick_us);
  EXPECT_EQ(c.emergency.comm_limit_ticks, d.emergency.comm_limit_ticks);
  EXPECT_EQ(c.sonar.timeout_ms, d.sonar.timeout_ms);
  EXPECT_EQ(c.sonar.schedule, d.sonar.schedule);
  EXPECT_EQ(c.sonar.moving_timeout_ms, d.sonar.moving_timeout_ms);
  EXPECT_EQ(c.robot.length_mm, d.robot.length_mm);
  // The whole safety core's section: the shipped file once said creep_cm_s = 10 against the
  // documented and compiled 20.
  const EmergencyConfig& e = c.emergency;
  const EmergencyConfig& f = d.emergency;
  EXPECT_EQ(e.mask, f.mask);
  EXPECT_EQ(e.min_safety_mm, f.min_safety_mm);
  EXPECT_EQ(e.safety_mm_per_cm_s, f.safety_mm_per_cm_s);
  EXPECT_EQ(e.motion_timeout_ms, f.motion_timeout_ms);
  EXPECT_EQ(e.auto_toggle, f.auto_toggle);
  EXPECT_EQ(e.latch, f.latch);
  EXPECT_EQ(e.rule, f.rule);
  EXPECT_EQ(e.margin_mm, f.margin_mm);
  EXPECT_EQ(e.creep_cm_s, f.creep_cm_s);
  EXPECT_EQ(e.free_age_ms, f.free_age_ms);
  EXPECT_EQ(e.narrow_arcs, f.narrow_arcs);
  EXPECT_EQ(e.protective_clear_ms, f.protective_clear_ms);
  EXPECT_EQ(e.reaction_ms, f.reaction_ms);
}

// [planner] map_file: relative to the configuration's folder; the geometry keys written are
// remembered (they must agree with the file, modules/planner/prior_map.cpp); no size check here.
TEST(Config, PlannerMapFileIsRelativeToTheConfigurationsFolder) {
  Config c;
  const auto err = parse_config("[planner]\nmap_file = \"maps/lab.map\"\ncell_mm = 50\nmap_width_mm = 900000\n",
                                "/etc/robuterd/robuterd.toml", c);
  ASSERT_FALSE(err) << err->message();
  EXPECT_EQ(c.planner.map_file, "/etc/robuterd/maps/lab.map");
  EXPECT_EQ(c.planner.map_file_line, 2);
  EXPECT_EQ(c.planner.geometry_lines[4], 3);  // cell_mm
  EXPECT_EQ(c.planner.geometry_lines[2], 4);  // map_width_mm
  EXPECT_EQ(c.planner.geometry_lines[0], 0);  // map_origin_x_mm: not written
  Config d;
  ASSERT_FALSE(parse_config("[planner]\nmap_file = \"/srv/lab.map\"\n", "robuterd.toml", d));
  EXPECT_EQ(d.planner.map_file, "/srv/lab.map");
}

// [places] grids_dir: relative to the configuration's folder like places.file; without a place
// graph it has no places to save, and is refused on its line.
TEST(Config, PlaceGridsFolderIsRelativeAndNeedsThePlaceGraph) {
  Config c;
  const auto err = parse_config("[places]\nfile = \"floor.places.toml\"\ngrids_dir = \"grids\"\n",
                                "/etc/robuterd/robuterd.toml", c);
  ASSERT_FALSE(err) << err->message();
  EXPECT_EQ(c.places.file, "/etc/robuterd/floor.places.toml");
  EXPECT_EQ(c.places.grids_dir, "/etc/robuterd/grids");
  Config d;
  ASSERT_FALSE(parse_config("[places]\nfile = \"f.toml\"\ngrids_dir = \"/var/lib/robuterd/grids\"\n", "r.toml", d));
  EXPECT_EQ(d.places.grids_dir, "/var/lib/robuterd/grids");
  Config e;
  const auto no_graph = parse_config("[places]\ngrids_dir = \"grids\"\n", "r.toml", e);
  ASSERT_TRUE(no_graph);
  EXPECT_NE(no_graph->message().find("r.toml:2: key 'places.grids_dir'"), std::string::npos) << no_graph->message();
  EXPECT_NE(no_graph->message().find("needs places.file"), std::string::npos) << no_graph->message();
  Config f;
  ASSERT_FALSE(parse_config("[places]\nfile = \"f.toml\"\ngrids_dir = \"g\"\nload_grids = true\n", "r.toml", f));
  EXPECT_TRUE(f.places.load_grids);
  Config g;
  const auto no_dir = parse_config("[places]\nfile = \"f.toml\"\nload_grids = true\n", "r.toml", g);
  ASSERT_TRUE(no_dir);
  EXPECT_NE(no_dir->message().find("r.toml:3: key 'places.load_grids'"), std::string::npos) << no_dir->message();
  EXPECT_NE(no_dir->message().find("needs places.grids_dir"), std::string::npos) << no_dir->message();
}

// Seed 003's initial count must stay below the threshold (a first miss would make an obstacle).
TEST(Config, PlannerInitialCountBelowTheThreshold) {
  Config c;
  EXPECT_FALSE(parse_config("[planner]\ninitial_count = 5\nhit_threshold = 10\n", "r.toml", c));
  EXPECT_EQ(c.planner.initial_count, 5u);
  const auto err = parse_config("[planner]\ninitial_count = 2\n", "r.toml", c);
  ASSERT_TRUE(err);
  EXPECT_EQ(err->message(), "r.toml:2: key 'planner.initial_count': 2 must be less than planner.hit_threshold 2 (a first "
                            "miss would make a cell an obstacle)");
}

}  // namespace
}  // namespace robuter
