// SPDX-License-Identifier: GPL-3.0-or-later
// Acceptance 3: an obstacle in the path — the drive gets zero speed in the tick the range was read.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "tests/safety_sim/reaction.hpp"

namespace robuter::test::safety_sim {
namespace {

// Runs `n` seeded trials of one kind and checks each: tripped on the obstacle, zero speed at the
// drive in the read tick, no contact. Returns the reaction times for the figures.
std::vector<std::int64_t> check_trials(bool teleport, int n) {
  std::vector<std::int64_t> reaction;
  std::printf("%-8s seed  AM        dist   safety  sensor range  appear→read  read→stop  rest clearance\n",
              teleport ? "teleport" : "approach");
  for (int seed = 1; seed <= n; ++seed) {
    const ReactionTrial t = random_trial(static_cast<std::uint64_t>(seed), teleport);
    SCOPED_TRACE(testing::Message() << (teleport ? "teleport" : "approach") << " seed " << seed << " AM " << t.left
                                    << " " << t.right << " distance " << t.distance);
    const ReactionResult r = run_trial(t);
    EXPECT_TRUE(r.ran) << r.error;
    if (!r.ran) continue;
    EXPECT_TRUE(r.tripped);
    EXPECT_EQ(r.cause, EmergencyCause::obstacle);
    EXPECT_GT(r.read_tick, 0u) << "no watch-dog reading under the safety distance was seen";
    EXPECT_GT(r.stop_tick, 0u) << "the drive never got zero speed";
    EXPECT_EQ(r.reaction_ticks(), 0) << "zero speed at the drive in the tick the range was read";
    EXPECT_FALSE(r.contact);
    EXPECT_GT(r.clearance_at_rest_mm, 0.0);
    reaction.push_back(r.reaction_ticks());
    std::printf("         %4d  %4d %4d  %4.2f m  %4u mm  %2d %5d mm  %5lld ticks  %3lld ticks  %6.1f mm\n", seed, t.left,
                t.right, t.distance, r.safety_mm, r.sensor, r.range_mm, static_cast<long long>(r.detection_ticks()),
                static_cast<long long>(r.reaction_ticks()), r.clearance_at_rest_mm);
  }
  return reaction;
}

TEST(Reaction, ApproachingAnObstacleZeroSpeedReachesTheDriveInTheReadTick) {
  auto v = check_trials(false, 12);
  std::sort(v.begin(), v.end());
  RecordProperty("approach_reaction_max_ticks", static_cast<int>(v.empty() ? -1 : v.back()));
}

TEST(Reaction, AnObstacleAppearingInThePathZeroSpeedReachesTheDriveInTheReadTick) {
  auto v = check_trials(true, 12);
  std::sort(v.begin(), v.end());
  RecordProperty("teleport_reaction_max_ticks", static_cast<int>(v.empty() ? -1 : v.back()));
}

}  // namespace
}  // namespace robuter::test::safety_sim
