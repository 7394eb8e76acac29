// SPDX-License-Identifier: GPL-3.0-or-later
// The localisation module on the whole firmware (issue #18): XW and XA, AC as the start pose,
// the map pose where the planner and the places read it, and tracking with a poor odometry.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "kernel/log.hpp"
#include "modules/firmware/sim_firmware.hpp"
#include "modules/localise/state_file.hpp"
#include "tests/localise/floor_tour.hpp"
#include "tests/support/log_capture.hpp"
#include "tests/support/temp_dir.hpp"

namespace robuter::test {
namespace {

Config floor_config() {
  Config cfg;
  cfg.places.file = ROBUTER_WORLDS_DIR "/building_floor.places.toml";
  cfg.localise.enabled = true;
  return cfg;
}

// XW's fields: state, x, y (0.1 mm), theta (0.01°), major, minor (mm), axis, sigma-theta,
// cluster %, particles, steps.
struct Where {
  std::string state;
  int x = 0, y = 0, theta = 0, major = 0, minor = 0, axis = 0, sigma = 0, cluster = 0, particles = 0, steps = 0;
};
Where where(SimFirmware& fw) {
  Where w;
  const std::string r = fw.ask("XW").value_or("");
  char state[32] = {};
  long long clock = 0;
  const int n = std::sscanf(r.c_str(), "W %31s %d %d %d %d %d %d %d %d %d %d %lld", state, &w.x, &w.y, &w.theta,
                            &w.major, &w.minor, &w.axis, &w.sigma, &w.cluster, &w.particles, &w.steps, &clock);
  EXPECT_EQ(n, 12) << r;
  w.state = state;
  return w;
}

TEST(LocaliseModule, WithoutLocalisationXWAndXAAreUnavailable) {
  SimFirmware fw;
  ASSERT_TRUE(fw.ok()) << fw.error();
  ASSERT_EQ(fw.ask("XB1"), "ack");
  EXPECT_EQ(fw.ask("XW"), "error 12 unavailable");
  EXPECT_EQ(fw.ask("XA"), "error 12 unavailable");
  EXPECT_EQ(fw.ask("XA 1 2 3"), "error 12 unavailable");
}

TEST(LocaliseModule, ACSetsTheStartXASetsThePoseOrStartsASearch) {
  SimFirmware fw(ROBUTER_WORLDS_DIR "/building_floor.toml", floor_config());
  ASSERT_TRUE(fw.ok()) << fw.error();
  fw.run_ticks(20);
  Where w = where(fw);
  EXPECT_EQ(w.state, "tracking");
  EXPECT_NEAR(w.x, 0, 100);  // the mean of the start cloud (0.1 m spread): within 1 cm
  EXPECT_NEAR(w.y, 0, 100);
  // The world's start, the west end of the corridor: AC says where the robot is.
  ASSERT_EQ(fw.ask("AC 30000 200500 0"), "ack");
  w = where(fw);  // read-your-writes: the next line sees the new pose
  EXPECT_EQ(w.state, "tracking");
  EXPECT_NEAR(w.x, 30000, 500);
  EXPECT_NEAR(w.y, 200500, 500);
  EXPECT_LE(w.major, 200);
  EXPECT_EQ(fw.ask("XN").value_or("").substr(0, 2), "N ");
  // XA moves the map pose only: BO (the odometry) stays.
  ASSERT_EQ(fw.ask("XA 40000 200500 0"), "ack");
  w = where(fw);
  EXPECT_NEAR(w.x, 40000, 500);
  EXPECT_EQ(fw.ask("BO").value_or("").substr(0, 16), "S 30000 200500 0");
  // Malformed or out of range: refused, nothing changed.
  ASSERT_EQ(fw.ask("XB1"), "ack");
  EXPECT_EQ(fw.ask("XA 1 2"), "error 2 bad-parameter-count");
  EXPECT_EQ(fw.ask("XA 1 2 -18000"), "error 4 out-of-range");
  fw.run_ticks(5);
  EXPECT_NEAR(where(fw).x, 40000, 500);
  // XA alone: a search over the whole floor.
  ASSERT_EQ(fw.ask("XA"), "ack");
  w = where(fw);
  EXPECT_EQ(w.state, "searching");
  EXPECT_LT(w.cluster, 50);  // the particles spread over the floor: no cluster holds them
}

// The map pose now, as BO gives it with [localise] report_corrected.
Eigen::Vector3d bo_pose(SimFirmware& fw) {
  const std::string bo = fw.ask("BO").value_or("");
  int x = 0, y = 0, theta = 0;
  EXPECT_EQ(std::sscanf(bo.c_str(), "S %d %d %d", &x, &y, &theta), 3) << bo;
  return {x * 1e-4, y * 1e-4, theta * 1e-2 * M_PI / 180.0};
}

// The simulated odometry misreads the left wheel by 3 %: along 8.6 m of corridor it drifts off by
// far more than the map pose, which the walls of the place graph keep within 15 cm and 4° of the
// truth (7.9 cm and 2.8° here).
TEST(LocaliseModule, TracksAlongTheCorridorWhereAPoorOdometryDrifts) {
  hal::SimOptions sim;
  sim.world_file = ROBUTER_WORLDS_DIR "/building_floor.toml";
  sim.seed = 3;
  sim.adjust = [](sim::SimConfig& c) { c.robot.odometry.scale_left = 0.03; };
  Config cfg = floor_config();
  cfg.localise.report_corrected = true;
  SimFirmware fw(ROBUTER_WORLDS_DIR "/building_floor.toml", cfg, sim);
  ASSERT_TRUE(fw.ok()) << fw.error();
  fw.run_ticks(20);
  ASSERT_EQ(fw.ask("AC 30000 200500 0"), "ack");
  ASSERT_EQ(fw.ask("ASN"), "ack");
  ASSERT_EQ(fw.ask("AM 30 30"), "ack");
  const auto& truth = fw.sim().robot().pose();
  double worst = 0.0, worst_heading = 0.0;
  for (int s = 0; s < 30; ++s) {
    fw.run_ticks(100);
    (void)fw.ask("AM 30 30");  // the communication watchdog: a line every second
    const Eigen::Vector3d m = bo_pose(fw);
    const double e = std::hypot(m.x() - truth.x, m.y() - truth.y);
    const double h = std::abs(std::remainder(m.z() - truth.theta, 2.0 * M_PI));
    if (std::getenv("ROBUTER_TRACE"))
      std::printf("t %d truth %.3f %.3f %.3f map %.3f %.3f %.3f  err %.3f\n", s, truth.x, truth.y, truth.theta, m.x(),
                  m.y(), m.z(), e);
    worst = std::max(worst, e);
    worst_heading = std::max(worst_heading, h);
  }
  ASSERT_EQ(fw.ask("AM 0 0"), "ack");
  const auto& odo = fw.sim().robot().odometry();
  const double odometry = std::hypot(odo.x - truth.x, odo.y - truth.y);
  EXPECT_GT(truth.x, 11.0) << "the robot drove less than 8 m";
  EXPECT_LT(worst, 0.15) << "odometry error at the end " << odometry;
  EXPECT_LT(worst_heading, 4.0 * M_PI / 180.0);
  EXPECT_GT(odometry, 0.3);
  EXPECT_EQ(where(fw).state, "tracking");
}

// Issue #18's tour (make bench: tools/bench/81-localise-firmware.sh, 30 minutes): an operator drives
// the floor's corridor loop, the simulator's odometry noise on (the ring's off: its spurious echoes
// are issue #19's), the safety core's walls placed by the map pose. Past corridor-b-4's door
// (≈ 365 s), a jamb's echo at a cone's edge 2.48 m away lay 12 cm from the jamb as a map pose
// 1.6° off places it: unexplained, its whole arc became hard evidence across the corridor and the
// robot stopped there for good (108 m driven in 30 minutes). With the heading's share in the
// structure's slack it goes on (532 m, map pose p95 70-75 mm and 1.3°).
TEST(LocaliseModule, TheOperatorsTourGoesOnPastTheDoorsWithTheWallsOnTheMapPose) {
  FloorTourSpec spec;
  spec.seconds = 420.0;
  spec.sonar_model = sim::SonarPreset::ideal;
  const FloorTourResult r = run_floor_tour(spec);
  ASSERT_TRUE(r.ok);
  EXPECT_GT(r.driven, 115.0) << "stopped for good (108 m: corridor-b-4's door)";
  EXPECT_EQ(r.protective_stops, 0u);
  EXPECT_LT(r.map_p95, 0.10);
  EXPECT_LT(r.map_heading_p95, 3.0 * M_PI / 180.0);
  EXPECT_GT(r.odometry_p95, 3.0 * r.map_p95) << "the odometry alone drifts far more";
}

// Why: issue #18's kidnapped robot (make bench: tools/bench/81-localise-firmware.sh, 30 seeded
// places). Carried 3 m along a corridor, the filter kept a compact cloud 3 m off: the walls look
// the same and recovery injected only past a share of 0.5, which a corridor never reaches (it
// rose to 0.2-0.46; tracking keeps it at 0.00), and then over the whole floor. Recovery now starts
// past 0.1, near the last compact estimate, mostly about its heading: these three places, at the
// first crossing and beside the east-west corridor's doors, are found within 30 s (0 of 30 seeded
// places before, 13 of 30 then: the rest lie in the north-south corridors, featureless for 13 m).
// Seeds 8 and 9 (corridor-b and the north-east corner) were not found even so: at the wrong place
// the ring explains as well as at the right one, augmented MCL's averages never part and nothing
// is drawn. The scouts along the heading line (docs/LOCALISATION.md, "Scouts") find both (found
// after 6.4 and 5.8 s; neither before them: checked), so the three must all be found.
TEST(LocaliseModule, ARobotCarriedAlongTheCorridorIsFoundAgain) {
  int found = 0;
  for (const std::uint64_t seed : {6u, 8u, 9u}) {  // firmware_tour_bench's places for these seeds
    FloorTourSpec spec;
    spec.seed = seed;
    spec.sonar_model = sim::SonarPreset::ideal;
    spec.kidnap = true;
    spec.kidnap_at = 60.0 + 41.0 * static_cast<double>(seed - 1);
    spec.kidnap_back = seed % 2 == 0;
    spec.seconds = 30.0;
    const FloorTourResult r = run_floor_tour(spec);
    ASSERT_TRUE(r.ok);
    ASSERT_GE(r.kidnapped_at, 0.0) << "seed " << seed << ": no clear spot 3 m along";
    if (r.found_after >= 0.0) ++found;
    // The scouts found it, and the firmware's report says so (Localisation::scouts_fired).
    EXPECT_GT(r.scouts_fired, 0u) << "seed " << seed;
    std::printf("seed %llu: carried at %.0f s from (%.1f, %.1f): found after %.1f s, scouts fired %u\n",
                static_cast<unsigned long long>(seed), r.kidnapped_at, r.kidnap_x, r.kidnap_y, r.found_after,
                r.scouts_fired);
  }
  EXPECT_EQ(found, 3);
}

// Why: along a north-south corridor the walls are the same for 13 m, and the ring hears what tells
// two places 3 m apart mostly as silences (no echo where the map has a wall head-on) and as far
// echoes the corridor's walls cannot explain (they meet the beam at grazing). The old model used
// neither: carried 3 m along that corridor (the realistic sonars, the first lap of seed 1), the
// robot was found within 30 s at 2 of these 5 moments (170 and 180 s); with the silences and the
// incidence at 4 (all but 180 s; docs/LOCALISATION.md, "The sonar model"); with recovery drawing
// along the heading line (2026-12-07) at 4 again (all but 120 s); with the scouts along the
// heading line (2026-12-07, later) at all 5, within 1.2-16 s. The sanitizer tree tries the same
// five (it tried two, 120 and 170 s, for time: the five took 18.7 s there in make test).
TEST(LocaliseModule, ARobotCarriedAlongANorthSouthCorridorIsFoundAgain) {
  const std::vector<double> moments = {100.0, 120.0, 150.0, 170.0, 180.0};
  const int needed = 5;
  int found = 0;
  for (const double at : moments) {
    FloorTourSpec spec;
    spec.seed = 1;
    spec.kidnap = true;
    spec.kidnap_at = at;
    spec.seconds = 30.0;
    const FloorTourResult r = run_floor_tour(spec);
    ASSERT_TRUE(r.ok);
    ASSERT_GE(r.kidnapped_at, 0.0) << at << " s: no clear spot 3 m along";
    if (r.found_after >= 0.0) ++found;
    std::printf("carried at %.0f s from (%.1f, %.1f): found after %.1f s\n", r.kidnapped_at, r.kidnap_x, r.kidnap_y, r.found_after);
  }
  EXPECT_GE(found, needed);
}

// Why: a bad input gets a clear error. A map with no cell where the robot fits (here walled up
// everywhere: every cell an obstacle) gave an empty free set, and a global search put every
// particle at the origin; start-up now stops, naming the localisation.
TEST(LocaliseModule, AMapWithNoPlaceTheRobotFitsStopsStartUp) {
  TempDir dir;
  ASSERT_TRUE(dir.ok());
  const std::string file = dir.file("walled.map");
  {
    std::ofstream out(file);
    out << "robuter-map 1\nwidth 8\nheight 8\nresolution 0.5\norigin -2 -2\nthreshold 2\ndata\n";
    for (int y = 0; y < 8; ++y) out << "0202020202020202\n";
  }
  Config cfg;
  cfg.planner.map_file = file;
  cfg.localise.enabled = true;
  (void)log_since_last();  // what start-up says, on its own
  {
    SimFirmware fw(ROBUTER_WORLDS_DIR "/empty.toml", cfg);
    EXPECT_FALSE(fw.ok());
  }
  const std::string said = log_since_last();
  EXPECT_NE(said.find("localise: the map (8 x 8 cells) has no place the robot fits"), std::string::npos) << said;
}

// [localise] state_file: the map pose a run leaves is where the next starts (its odometry at 0);
// a broken file is said and ignored; a missing folder stops start-up naming the key.
TEST(LocaliseModule, TheMapPoseIsKeptAcrossARestart) {
  TempDir dir;
  ASSERT_TRUE(dir.ok());
  Config cfg = floor_config();
  cfg.localise.state_file = dir.file("pose.txt");
  {
    SimFirmware fw(ROBUTER_WORLDS_DIR "/building_floor.toml", cfg);
    ASSERT_TRUE(fw.ok()) << fw.error();
    ASSERT_EQ(fw.ask("AC 30000 200500 0"), "ack");
    ASSERT_EQ(fw.ask("XA 40000 200500 9000"), "ack");  // tracking: kept within a second
    fw.run_ticks(150);
  }
  std::string why;
  const auto kept = localise::read_state_file(cfg.localise.state_file, why);
  ASSERT_TRUE(kept) << why;
  EXPECT_NEAR(kept->x, 40000, 500);
  EXPECT_NEAR(kept->y, 200500, 500);
  EXPECT_NEAR(kept->theta, 9000, 300);
  {
    SimFirmware fw(ROBUTER_WORLDS_DIR "/building_floor.toml", cfg);
    ASSERT_TRUE(fw.ok()) << fw.error();
    fw.run_ticks(20);
    const Where w = where(fw);
    EXPECT_EQ(w.state, "tracking");
    EXPECT_NEAR(w.x, 40000, 500);
    EXPECT_NEAR(w.y, 200500, 500);
    EXPECT_NEAR(w.theta, 9000, 300);
    EXPECT_EQ(fw.ask("BO").value_or("").substr(0, 8), "S 0 0 0 ");  // the odometry starts at 0
  }
  {
    std::FILE* f = std::fopen(cfg.localise.state_file.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("robuter-localise 9\npose 400000 200500 0\n", f);  // a valid pose under a wrong header
    std::fclose(f);
    SimFirmware fw(ROBUTER_WORLDS_DIR "/building_floor.toml", cfg);
    ASSERT_TRUE(fw.ok()) << fw.error();
    fw.run_ticks(20);
    EXPECT_NEAR(where(fw).x, 0, 500);  // ignored: the odometry's start
  }
  cfg.localise.state_file = dir.file("no-such-folder/pose.txt");
  SimFirmware fw(ROBUTER_WORLDS_DIR "/building_floor.toml", cfg);
  EXPECT_FALSE(fw.ok());
  EXPECT_NE(fw.error().find("localise.state_file"), std::string::npos) << fw.error();
}

// The state file's reader refuses what is not one: a wrong header, a malformed or out-of-range
// pose, an empty file, a folder.
TEST(LocaliseStateFile, RefusesWhatIsNotAStateFileAndReadsWhatItWrites) {
  TempDir dir;
  ASSERT_TRUE(dir.ok());
  const std::string path = dir.file("pose.txt");
  std::string why;
  ASSERT_TRUE(localise::write_state_file(path, {123, -456, 18000}, why)) << why;
  const auto back = localise::read_state_file(path, why);
  ASSERT_TRUE(back) << why;
  EXPECT_EQ(back->x, 123);
  EXPECT_EQ(back->y, -456);
  EXPECT_EQ(back->theta, 18000);
  for (const char* text : {"", "robuter-localise 2\npose 1 2 3\n", "robuter-localise 1\n", "robuter-localise 1\npose 1 2\n",
                           "robuter-localise 1\npose 1 2 3 4\n", "robuter-localise 1\npose 1 2 -18000\n",
                           "robuter-localise 1\npose 1 99999999999 3\n", "robuter-localise 1\npose 1 2 4294967396\n",
                           "robuter-localise 1\nplace 1 2 3\n"}) {
    std::FILE* f = std::fopen(path.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs(text, f);
    std::fclose(f);
    why.clear();
    EXPECT_FALSE(localise::read_state_file(path, why)) << text;
    EXPECT_NE(why.find(path), std::string::npos) << why;
  }
  EXPECT_FALSE(localise::read_state_file(dir.file(""), why));  // the folder itself
}

}  // namespace
}  // namespace robuter::test
