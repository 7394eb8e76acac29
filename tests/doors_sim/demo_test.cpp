// SPDX-License-Identifier: GPL-3.0-or-later
// The demonstration course on the whole simulated firmware in worlds/seed002_course.toml: laps
// with their three-phase calibration, odometry noise on; the true pose at every recalibration
// point against where it should be (5.0 m, 1.6 m, 180°) — the end-of-lap error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "modules/firmware/sim_firmware.hpp"
#include "tests/support/sample.hpp"

namespace robuter {
namespace {

struct LapError {
  double position_mm;  // distance from the recalibration point, mm
  double heading_deg;  // heading error, degrees
};

// Runs `laps` laps; the error of each lap's end. Contact or an emergency ends the run early.
// `xd`: the XD reply once the laps are done and the robot has had 1 s to stop.
// `where`, if given: the XE reply and the true pose at the end (why a run stopped short).
std::vector<LapError> run_laps(std::uint32_t laps, bool odometry_noise, std::uint64_t seed, bool* contact, std::string* xd,
                               sim::SonarPreset sonar = sim::SonarPreset::ideal, std::string* where = nullptr) {
  Config cfg;
  cfg.demo.enabled = true;
  cfg.demo.laps = laps;
  hal::SimOptions sim;
  sim.odometry_noise = odometry_noise;
  sim.sonar_model = sonar;
  sim.seed = seed;
  test::SimFirmware fw(ROBUTER_WORLDS_DIR "/seed002_course.toml", cfg, sim);
  EXPECT_TRUE(fw.ok()) << fw.error();
  std::vector<LapError> out;
  *contact = false;
  fw.set_tick_observer([&] { *contact = *contact || fw.sim().robot().bumper(); });
  std::uint32_t seen = 0;
  for (int i = 0; i < 200 * 100 * static_cast<int>(laps) && seen < laps; ++i) {
    fw.step();
    if (i % 1000 == 0) fw.ask("BC");  // a client keeps the link alive
    const DemoStatus& d = fw.bb().demo_status.reader().peek();
    if (d.laps > seen) {
      seen = d.laps;
      const auto& p = fw.sim().robot().pose();
      const double dh = std::remainder(p.theta * 180.0 / M_PI - 180.0, 360.0);
      out.push_back({1000.0 * std::hypot(p.x - 5.0, p.y - 1.6), dh});
      std::printf("lap %u: end (%.3f m, %.3f m, %.1f°): %.0f mm, %.2f° from the recalibration point (side %d mm, circle %d mm)\n",
                  d.laps, p.x, p.y, p.theta * 180.0 / M_PI, out.back().position_mm, out.back().heading_deg, d.side_mm,
                  d.radius_mm);
    }
    if (fw.bb().emergency.reader().peek().latched) break;
  }
  fw.run_ticks(100);
  *xd = fw.ask("XD").value_or("");
  if (where != nullptr) {
    const auto& p = fw.sim().robot().pose();
    char pose[96];
    std::snprintf(pose, sizeof pose, " at (%.2f m, %.2f m, %.0f deg)", p.x, p.y, p.theta * 180.0 / M_PI);
    *where = fw.ask("XE").value_or("") + pose;
  }
  EXPECT_EQ(fw.sim().robot().wheel_speeds().left, 0.0);
  EXPECT_EQ(fw.sim().robot().wheel_speeds().right, 0.0);
  return out;
}

// Laps from `seed`: all done without contact, each end within the bounds; prints the figures.
void check_laps(std::uint32_t laps, bool noise, std::uint64_t seed, double max_mm, double max_deg,
                sim::SonarPreset sonar = sim::SonarPreset::ideal) {
  bool contact = false;
  std::string xd;
  const std::vector<LapError> e = run_laps(laps, noise, seed, &contact, &xd, sonar);
  ASSERT_EQ(e.size(), laps) << xd;
  EXPECT_FALSE(contact);
  double worst = 0.0, sum = 0.0, worst_deg = 0.0;
  for (const LapError& l : e) {
    worst = std::max(worst, l.position_mm);
    worst_deg = std::max(worst_deg, std::abs(l.heading_deg));
    sum += l.position_mm;
    EXPECT_LT(l.position_mm, max_mm);
    EXPECT_LT(std::abs(l.heading_deg), max_deg);
  }
  EXPECT_NE(xd.find(" finished none done " + std::to_string(laps) + " "), std::string::npos) << xd;
  std::printf("end-of-lap error%s%s (seed %llu): mean %.0f mm, worst %.0f mm, worst heading %.1f° over %zu laps\n",
              noise ? " with odometry noise" : "", sonar == sim::SonarPreset::realistic ? " and the realistic sonar" : "",
              static_cast<unsigned long long>(seed), sum / static_cast<double>(e.size()),
              worst, worst_deg, e.size());
}

// Five laps (the figure) with encoder noise, slip, scale and wheel-base errors, from two
// seeds: every lap ends back on the recalibration point, the error does not grow from lap to lap
// (the calibration resets it), and the module then stops and says so (XD: finished).
TEST(Demo, FiveLapsWithOdometryNoiseEndOnTheRecalibrationPoint) {
  check_laps(5, true, 7, 120.0, 5.0);
  if (!test::kSanitized) check_laps(5, true, 11, 120.0, 5.0);  // under the sanitizers one seed is the sample
}

// Issue #19: the same five laps with the realistic sonar model (multipath, cross-talk, lost and
// spurious echoes) as well: the calibration on the boxes (medians of three readings) still holds
// every lap's end. Seed 7; seeds 11, 14, 16 and 17 of 1–20 are held for good by protective stops
// (docs/SIMULATOR.md, "With the calibration's medians"; docs/SAFETY.md §13, "Still open").
//
// ROBUTER_DEMO_SEEDS=N runs seeds 1..N instead and prints, for each, the laps driven and the
// worst end-of-lap error, then how many ran every lap and how many within 120 mm every lap (the
// survey docs/SIMULATOR.md's table gives; no assertion but contact).
TEST(Demo, FiveLapsWithTheRealisticSonarEndOnTheRecalibrationPoint) {
  if (const char* seeds = std::getenv("ROBUTER_DEMO_SEEDS")) {
    const int n = std::atoi(seeds);
    int all_laps = 0, within = 0;
    for (int seed = 1; seed <= n; ++seed) {
      bool contact = false;
      std::string xd, where;
      const std::vector<LapError> e = run_laps(5, true, static_cast<std::uint64_t>(seed), &contact, &xd,
                                               sim::SonarPreset::realistic, &where);
      double worst = 0.0, worst_deg = 0.0, sum = 0.0;
      for (const LapError& l : e) {
        worst = std::max(worst, l.position_mm);
        worst_deg = std::max(worst_deg, std::abs(l.heading_deg));
        sum += l.position_mm;
      }
      EXPECT_FALSE(contact) << "seed " << seed;
      all_laps += e.size() == 5 ? 1 : 0;
      within += e.size() == 5 && worst < 120.0 ? 1 : 0;
      std::printf("survey seed %d: %zu of 5 laps, mean %.0f mm, worst %.0f mm, %.1f deg; XD %s; XE %s\n", seed, e.size(),
                  e.empty() ? 0.0 : sum / static_cast<double>(e.size()), worst, worst_deg, xd.c_str(), where.c_str());
    }
    std::printf("survey: %d of %d seeds ran 5 laps, %d within 120 mm every lap\n", all_laps, n, within);
    return;
  }
  check_laps(5, true, 7, 120.0, 5.0, sim::SonarPreset::realistic);
}

TEST(Demo, LapsWithExactOdometry) { check_laps(2, false, 1, 40.0, 2.0); }

// Without the calibration boxes the course cannot calibrate: it stops within the limit, the
// robot stands still and XD says why.
TEST(Demo, MissingBoxesEndInNoLandmark) {
  std::ifstream in(ROBUTER_WORLDS_DIR "/seed002_course.toml");
  std::stringstream text;
  text << in.rdbuf();
  std::string w = text.str();
  for (std::size_t at; (at = w.find("[[box]]")) != std::string::npos;) w.erase(at, w.find("\n\n", at) - at);  // each box table
  const std::string path = (std::filesystem::temp_directory_path() / ("robuter-demo-" + std::to_string(::getpid()) + ".toml")).string();
  std::ofstream(path) << w;
  Config cfg;
  cfg.demo.enabled = true;
  cfg.demo.calibration_timeout_ticks = 1500;
  test::SimFirmware fw(path, cfg);
  ASSERT_TRUE(fw.ok()) << fw.error();
  std::filesystem::remove(path);
  const bool ended = fw.run_until([&] { return fw.bb().demo_status.reader().peek().state == ModeState::failed; }, 20000);
  ASSERT_TRUE(ended);
  fw.run_ticks(100);
  EXPECT_EQ(fw.sim().robot().wheel_speeds().left, 0.0);
  EXPECT_EQ(fw.sim().robot().wheel_speeds().right, 0.0);
  const std::string xd = *fw.ask("XD");
  EXPECT_NE(xd.find(" failed no-landmark failed 0 "), std::string::npos) << xd;
}

}  // namespace
}  // namespace robuter
