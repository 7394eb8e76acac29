// SPDX-License-Identifier: GPL-3.0-or-later
// Multipath against the evidence grid: an echo's cone clears no real surface's evidence (docs/SAFETY.md §13).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "modules/emergency/ring_envelope.hpp"
#include "tests/safety_sim/multipath_census.hpp"
#include "tests/support/sample.hpp"

namespace robuter::test {
namespace {

constexpr std::uint64_t kFresh = 300;  // 3 s of 10 ms ticks: free_age_ms, single_echo_ms

// The firmware's grid (the robot model's cone and blanking, "Unconfirmed" and the line of sight's
// protection at 3 s of 10 ms ticks),
// without known structure: every arc is marked whole.
emergency::GridSettings firmware_grid() {
  emergency::GridSettings g = emergency::grid_settings(EmergencyConfig{});
  g.single_age = kFresh;
  g.sight_age = kFresh;
  return g;
}

// A wanderer's realistic ring on the building floor (long grazing corridor walls: 3.1 % of its
// readings are multipath) and in the lab. With echoes clearing evidence seen from any line of
// sight, anywhere in their cone (the rule before), the bounced readings cleared thousands of cells
// of the very walls other sensors had marked; along nearly the evidence's own line of sight, well
// inside the cone, of the evidence at most 3 s old less than a tenth remains (an arc's cell that
// lies on a surface the echo did not come from; a solid's corner, where the surface ends inside
// the cone: docs/SAFETY.md §13, "Multipath"). ROBUTER_MULTIPATH_SECONDS runs longer (make bench).
TEST(Multipath, BouncedEchoesClearATenthOfTheFreshEvidenceOfRealSurfacesTheyDidBefore) {
  const char* env = std::getenv("ROBUTER_MULTIPATH_SECONDS");
  // Under the sanitizers (ten times the cost) a shorter sample of the same paths.
  const double seconds = env != nullptr ? std::atof(env) : test::kSanitized ? 40.0 : 240.0;
  for (const char* name : {"default.toml", "building_floor.toml"}) {
    if (test::kSanitized && env == nullptr && std::string(name) != "default.toml") continue;  // the lab only
    const std::string world = std::string(ROBUTER_SHIPPED_WORLDS) + "/" + name;
    emergency::GridSettings any_line = firmware_grid();
    any_line.sight_age = 1;  // every reading's evidence is a batch old: any farther echo clears it
    const MultipathCensus before = multipath_census(world, sim::SonarPreset::realistic, seconds, 1, any_line, kFresh);
    const MultipathCensus now = multipath_census(world, sim::SonarPreset::realistic, seconds, 1, firmware_grid(), kFresh);
    for (const auto& [rule, c] : {std::pair{"any line of sight", before}, std::pair{"along its line of sight", now}})
      std::printf("multipath %s, %.0f s, echoes clear evidence %s: %ld readings (%ld longer than the ideal model's), "
                  "%.0f m driven; cleared %ld cells on a surface (%ld of evidence at most 3 s old, %ld at a corner), %ld off every surface; %ld cell-seconds of evidence off every surface within 1.5 m\n",
                  name, seconds, rule, c.readings, c.longer_than_truth, c.travelled, c.surface_cleared, c.fresh_cleared, c.corner_cleared, c.phantom_cleared,
                  c.phantom_near);
    ASSERT_GT(before.readings, 0) << world;
    EXPECT_GT(before.surface_cleared, 0) << "the census sees the rule before";
    EXPECT_GT(before.fresh_cleared, 0) << "the census sees the rule before";
    // The full sample: a tenth at most (lab 192 of 2,426, floor 299 of 17,270); the sanitizers'
    // 40 s in the lab, fewer (4 of 234).
    EXPECT_LT(now.fresh_cleared * (test::kSanitized ? 1 : 10), before.fresh_cleared) << name;
  }
}

}  // namespace
}  // namespace robuter::test
