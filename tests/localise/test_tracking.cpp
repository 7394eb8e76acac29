// SPDX-License-Identifier: GPL-3.0-or-later
// The filter on the simulated lab: tracking where odometry drifts, and recovery from a kidnapping.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "hal/sim/rng.hpp"
#include "hal/sim/sonar.hpp"
#include "hal/sim/sonar_layout.hpp"
#include "tests/localise/lab_tour.hpp"

namespace robuter::loc {
namespace {

using test::lab_loop;

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(Tracking, ThreeLapsOfTheLabStayWithin10cmWhereOdometryDrifts) {
  const auto lab = test::load_lab("default.toml");
  for (std::uint64_t seed = 1; seed <= 2; ++seed) {
    auto spec = lab_loop(seed);
    spec.laps = 3;
    const auto samples = test::run_tour(lab, spec);
    ASSERT_GT(samples.size(), 100u);
    std::vector<double> pos, head;
    for (const auto& t : samples) {
      pos.push_back(t.filter_error);
      head.push_back(t.filter_heading);
    }
    const double p95 = test::quantile(pos, 0.95), h95 = test::quantile(head, 0.95);
    const double worst = test::quantile(pos, 1.0);
    const auto& last = samples.back();
    std::printf("seed %llu: %zu steps over %.0f s; filter p95 %.0f mm %.2f deg, worst %.0f mm; "
                "odometry at the end %.0f mm %.1f deg; particles at the end %d; scouts fired %d\n",
                static_cast<unsigned long long>(seed), samples.size(), last.time, p95 * 1000, h95 / kDeg,
                worst * 1000, last.odometry_error * 1000, last.odometry_heading / kDeg, last.particles, last.scouts_fired);
    EXPECT_LE(p95, 0.10);
    EXPECT_EQ(last.scouts_fired, 0);             // no scout takes a tracked pose for a carry
    EXPECT_LE(h95, 3.0 * kDeg);
    EXPECT_LE(worst, 0.30);                      // never diverging
    EXPECT_GT(last.odometry_error, 3.0 * p95);   // the tour is one odometry alone would lose
  }
}

TEST(Tracking, AKidnappedRobotIsFoundAgain) {
  const auto lab = test::load_lab("default.toml");
  int recovered = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    auto spec = lab_loop(seed);
    spec.laps = 3;
    spec.kidnap_after = 20.0;
    spec.kidnap_to_waypoint = 5;  // (6.6, 2.3): from the west room to the east one, over 3 m
    const auto samples = test::run_tour(lab, spec);
    const double at = test::found_after(samples, 20.0);
    const double found = at < 0.0 ? -1.0 : at - 20.0;
    std::printf("seed %llu: found %.1f s after the kidnapping\n", static_cast<unsigned long long>(seed), found);
    if (found >= 0.0 && found <= 30.0) ++recovered;
  }
  EXPECT_GE(recovered, 2);
}

}  // namespace
}  // namespace robuter::loc

namespace robuter::loc {
namespace {

TEST(Tracking, GlobalLocalisationFindsTheRobotWithNoInitialPose) {
  const auto lab = test::load_lab("default.toml");
  int found_in_time = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    auto spec = lab_loop(seed);
    spec.laps = 2;
    spec.global_start = true;
    const auto samples = test::run_tour(lab, spec);
    const double found = test::found_after(samples);
    std::printf("seed %llu: found after %.1f s of driving\n", static_cast<unsigned long long>(seed), found);
    if (found >= 0.0 && found <= 60.0) ++found_in_time;
  }
  EXPECT_GE(found_in_time, 2);
}

}  // namespace
}  // namespace robuter::loc

namespace robuter::loc {
namespace {

// At a corridor crossing the ring hears little while the robot turns: the likelihood drops, the
// recovery injects random particles over the floor, and a mean of the whole cloud jumped 0.7 m
// (docs/LOCALISATION.md, "The estimate"). The estimate is the densest cluster's.
TEST(Tracking, TurningAtACorridorCrossingKeepsTheEstimate) {
  const auto floor = test::load_lab("building_floor.toml");
  for (std::uint64_t seed = 1; seed <= 2; ++seed) {
    test::TourSpec spec;
    spec.waypoints = {{13.0, 20.05}, {21.15, 20.05}, {21.15, 27.0}, {21.15, 20.05}, {30.0, 20.05}};
    spec.start = Pose(13.0, 20.05, 0.0);
    spec.seed = seed;
    test::use_simulator_odometry_noise(spec);
    const auto samples = test::run_tour(floor, spec);  // and back along the corridor to (13, 20.05)
    double worst = 0.0;
    for (const auto& t : samples) worst = std::max(worst, t.filter_error);
    std::printf("seed %llu: %zu steps, worst %.0f mm\n", static_cast<unsigned long long>(seed), samples.size(), worst * 1000);
    EXPECT_LT(worst, 0.30);
  }
}

}  // namespace
}  // namespace robuter::loc

namespace robuter::loc {
namespace {

// Why: issue #18's kidnappings. Carried along a corridor the robot hears what it heard before (two
// side walls, nothing ahead or behind), and recovery's random particles must land near it: drawn
// uniformly within 4 m of the estimate, few fall on the corridor's axis. Half of them are now
// drawn along the estimate's heading line, 0.25 m (one sigma) across it. In a room, where the
// disc is free all round: of the particles injected (farther than 0.6 m from the estimate), 43 %
// lie within 0.3 m of the heading line (84 of 194; the disc alone: 8 %, 50 of 637).
TEST(Tracking, RecoveryDrawsHalfItsParticlesAlongTheHeadingLine) {
  const auto floor = test::load_lab("building_floor.toml");
  sim::SonarModel sonar(floor.world, sim::default_ring_params());
  const auto layout = sim::default_ring_layout();
  sim::Rng rng(3);
  FilterParams params;
  params.recovery_readings = 1;  // room-05's walls are mostly out of reach: every echo counts
  params.scouts = 0;             // augmented MCL's draws alone (a scout's are on the line too)
  ParticleFilter filter(floor.field, params, 21);
  const Pose truth(6.0, 28.0, 0.3);  // room-05, clear of the lectern and the rows within 4 m
  filter.set_pose(truth, Eigen::Vector3d(0.02, 0.02, 0.01));
  std::vector<SonarReading> readings(layout.size());
  const auto read = [&](double scale) {
    for (std::size_t s = 0; s < layout.size(); ++s) {
      const double r = sonar.measure(sim::Pose{truth.x(), truth.y(), truth.z()}, layout[s], &rng);
      readings[s] = SonarReading{layout[s].position, layout[s].direction, r * scale};
    }
  };
  int steps = 0, injected = 0, far = 0, on_line = 0;
  for (int k = 1; k <= 40 && injected < 200; ++k) {
    read(k <= 10 ? 1.0 : 0.6);  // the ring as the map has it, then ranges the map cannot explain
    if (!filter.step(Pose(0.01 * k, 0.0, 0.11 * k), readings)) continue;  // turning in place
    ++steps;
    if (filter.injected() == 0) continue;
    injected += filter.injected();
    const Pose& e = filter.estimate().pose;
    const Eigen::Vector2d dir(std::cos(e.z()), std::sin(e.z()));
    for (const auto& p : filter.particles()) {
      const Eigen::Vector2d d(p.pose.x() - e.x(), p.pose.y() - e.y());
      if (d.norm() < 0.6) continue;
      ++far;
      if (std::abs(dir.x() * d.y() - dir.y() * d.x()) < 0.3) ++on_line;
    }
  }
  std::printf("%d steps, %d injected, %d far, %d of them within 0.3 m of the heading line\n", steps, injected, far, on_line);
  ASSERT_GT(far, 100);
  EXPECT_GT(on_line, far * 3 / 10);
}

// The scouts (FilterParams::scouts): poses on the estimate's heading line, half ahead and half
// behind at scout_spacing steps, the estimate first; one that does not fit the map is not weighed.
TEST(Scouts, StandOnTheEstimatesHeadingLineAndNoneFitsInAWall) {
  const auto floor = test::load_lab("building_floor.toml");
  FilterParams params;
  ParticleFilter filter(floor.field, params, 5);
  filter.set_pose(Pose(19.0, 20.05, 0.0), Eigen::Vector3d(0.01, 0.01, 0.005));  // corridor-ew, facing east
  const auto scouts = filter.scouts();
  ASSERT_EQ(scouts.size(), static_cast<std::size_t>(params.scouts + 1));
  const Pose e = filter.estimate().pose;
  EXPECT_EQ(scouts[0].pose, e);
  std::vector<double> along;
  for (std::size_t i = 1; i < scouts.size(); ++i) {
    const Pose d = scouts[i].pose - e;
    along.push_back(d.x() * std::cos(e.z()) + d.y() * std::sin(e.z()));
    EXPECT_NEAR(-d.x() * std::sin(e.z()) + d.y() * std::cos(e.z()), 0.0, 1e-9);
    EXPECT_EQ(scouts[i].pose.z(), e.z());
    EXPECT_EQ(scouts[i].evidence, 0.0);
    const Eigen::Vector2d at(scouts[i].pose.x(), scouts[i].pose.y());
    EXPECT_EQ(scouts[i].free, floor.field.at(at) >= params.body_clearance) << i;
  }
  std::sort(along.begin(), along.end());
  for (int k = 0; k < params.scouts / 2; ++k) {
    EXPECT_NEAR(along[static_cast<std::size_t>(k)], -params.scout_spacing * (params.scouts / 2 - k), 1e-9);
    EXPECT_NEAR(along[static_cast<std::size_t>(params.scouts / 2 + k)], params.scout_spacing * (k + 1), 1e-9);
  }
  // Facing across corridor-ew, the line runs through its walls: a pose the robot cannot take there
  // is not weighed.
  filter.set_pose(Pose(19.0, 19.2, 0.5 * std::numbers::pi), Eigen::Vector3d(0.01, 0.01, 0.005));
  int walled = 0;
  for (const auto& sc : filter.scouts()) walled += sc.free ? 0 : 1;
  EXPECT_GT(walled, 0);
}

// Why: issue #18's kidnappings along a corridor. The filter believes the robot 3 m behind where it
// is, on corridor-ew facing east from x = 25 m and on corridor-a facing north from y = 24 m (past
// the crossing: walls and doors for 13 m), and the ring's walls are the same at both. Augmented
// MCL's averages hardly part (a crossing or a door is a few readings of a step) and nothing is
// drawn: without scouts neither is found within 8 m. A scout 3 m ahead explains those readings,
// fires, and the filter takes the carry.
TEST(Scouts, ACarryAlongACorridorIsFoundWhereTheRingTellsIt) {
  const auto floor = test::load_lab("building_floor.toml");
  sim::SonarModel sonar(floor.world, sim::default_ring_params());
  const auto layout = sim::default_ring_layout();
  std::vector<SonarReading> readings(layout.size());
  // From `start` (true pose) 8 m along its heading at 0.1 m a step, the filter told it was 3 m
  // behind; how far off the estimate ends.
  const auto run = [&](const Pose& start, int scouts) {
    FilterParams params;
    params.scouts = scouts;
    ParticleFilter filter(floor.field, params, 7);
    sim::Rng rng(11);
    const Eigen::Vector2d dir(std::cos(start.z()), std::sin(start.z()));
    filter.set_pose(Pose(start.x() - 3.0 * dir.x(), start.y() - 3.0 * dir.y(), start.z()), Eigen::Vector3d(0.05, 0.05, 0.02));
    double error = 0.0;
    for (int k = 0; k <= 80; ++k) {
      const Pose truth(start.x() + 0.1 * k * dir.x(), start.y() + 0.1 * k * dir.y(), start.z());
      for (std::size_t s = 0; s < layout.size(); ++s) {
        const double r = sonar.measure(sim::Pose{truth.x(), truth.y(), truth.z()}, layout[s], &rng);
        readings[s] = SonarReading{layout[s].position, layout[s].direction, r};
      }
      filter.step(Pose(0.1 * k, 0.0, 0.0), readings);
      error = std::hypot(filter.estimate().pose.x() - truth.x(), filter.estimate().pose.y() - truth.y());
    }
    std::printf("from (%.2f, %.2f), scouts %d: fired %d times; at the end %.0f mm off\n", start.x(), start.y(), scouts,
                filter.scouts_fired(), error * 1000.0);
    return error;
  };
  for (const Pose& start : {Pose(25.0, 20.05, 0.0), Pose(21.15, 24.0, 0.5 * std::numbers::pi)}) {
    EXPECT_GT(run(start, 0), 2.0);   // not found: the cloud stays about 3 m behind
    EXPECT_LT(run(start, 16), 0.2);  // found
  }
}

// Why: #17's routes 5 and 7 (tools/bench/70-places.sh, odometry noise, [localise]) ended
// `unreachable` with the first scouts: in rooms whose walls are mostly out of the ring's reach,
// steps of three to five echoes (an unmapped bench's among them) fired scouts, and the estimate
// jumped. A step with fewer than recovery_readings echoes gives no scout evidence, as it moves
// none of augmented MCL's averages (10 of 10 routes again).
TEST(Scouts, AStepOfAFewEchoesIsNoEvidence) {
  const auto floor = test::load_lab("building_floor.toml");
  sim::SonarModel sonar(floor.world, sim::default_ring_params());
  const auto layout = sim::default_ring_layout();
  FilterParams params;
  ParticleFilter filter(floor.field, params, 7);
  sim::Rng rng(11);
  const Pose start(25.0, 20.05, 0.0);  // the carry of ACarryAlongACorridorIsFoundWhereTheRingTellsIt
  filter.set_pose(Pose(start.x() - 3.0, start.y(), start.z()), Eigen::Vector3d(0.05, 0.05, 0.02));
  std::vector<SonarReading> readings;
  double most = 0.0;
  for (int k = 0; k <= 80; ++k) {
    const Pose truth(start.x() + 0.1 * k, start.y(), start.z());
    readings.clear();
    for (std::size_t s = 0; s < layout.size(); ++s) {
      const double r = sonar.measure(sim::Pose{truth.x(), truth.y(), truth.z()}, layout[s], &rng);
      SonarReading reading{layout[s].position, layout[s].direction, r};
      const int echoes = static_cast<int>(std::count_if(readings.begin(), readings.end(), [&](const SonarReading& x) {
        return informative(x, params.sonar);
      }));
      if (!informative(reading, params.sonar) || echoes < params.recovery_readings - 1) readings.push_back(reading);
    }
    filter.step(Pose(0.1 * k, 0.0, 0.0), readings);
    for (const auto& sc : filter.scouts()) most = std::max(most, sc.evidence);
  }
  EXPECT_EQ(filter.scouts_fired(), 0);
  EXPECT_EQ(most, 0.0);
}

}  // namespace
}  // namespace robuter::loc
