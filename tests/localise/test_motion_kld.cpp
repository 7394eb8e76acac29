// SPDX-License-Identifier: GPL-3.0-or-later
// The odometry motion model (exact without noise, forwards and backwards) and KLD-sampling.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "modules/localise/lib/kld_bins.hpp"
#include "modules/localise/lib/motion_model.hpp"

namespace robuter::loc {
namespace {

TEST(MotionModel, WithoutNoiseAParticleMovesAsTheOdometryDidInItsOwnFrame) {
  std::mt19937_64 rng(1);
  const MotionNoise none{0.0, 0.0, 0.0, 0.0};
  const Pose cases[][2] = {
      {Pose(0, 0, 0), Pose(1, 0, 0)},                // straight on
      {Pose(0, 0, 0), Pose(-0.5, 0, 0)},             // backwards
      {Pose(1, 2, 0.3), Pose(1, 2, 1.9)},            // a turn in place
      {Pose(1, 2, 3.0), Pose(0.2, 2.4, -2.9)},       // across the +-pi seam
      {Pose(0, 0, 1.0), Pose(-0.3, -0.4, 1.2)},      // backwards and turning
  };
  for (const auto& c : cases) {
    const OdometryStep s = odometry_step(c[0], c[1]);
    // The same increment applied to a particle elsewhere: rotate the odometry's displacement.
    const Pose start(5.0, -1.0, 0.7);
    const Pose got = sample_motion(start, s, none, rng);
    const double d = start.z() - c[0].z();
    const Eigen::Vector2d delta(c[1].x() - c[0].x(), c[1].y() - c[0].y());
    const Eigen::Vector2d want = Eigen::Vector2d(start.x(), start.y()) +
                                 Eigen::Rotation2Dd(d) * delta;
    EXPECT_NEAR(got.x(), want.x(), 1e-9);
    EXPECT_NEAR(got.y(), want.y(), 1e-9);
    EXPECT_NEAR(wrap_angle(got.z() - (start.z() + c[1].z() - c[0].z())), 0.0, 1e-9);
    EXPECT_LE(std::abs(s.rot1), std::numbers::pi / 2 + 1e-12);  // a reverse is no half turn
  }
}

TEST(MotionModel, TheSpreadGrowsWithTheDistanceDriven) {
  std::mt19937_64 rng(3);
  const MotionNoise noise;
  const auto spread = [&](double metres) {
    const OdometryStep s = odometry_step(Pose(0, 0, 0), Pose(metres, 0, 0));
    double sum = 0.0;
    for (int i = 0; i < 4000; ++i) sum += std::pow(sample_motion(Pose(0, 0, 0), s, noise, rng).x() - metres, 2);
    return std::sqrt(sum / 4000);
  };
  const double a = spread(0.2), b = spread(0.8);
  EXPECT_NEAR(a, std::sqrt(noise.trans_from_trans) * 0.2, 0.1 * a);
  EXPECT_NEAR(b / a, 4.0, 0.4);
}

TEST(Kld, TheBoundGrowsWithTheBinsAndTheSetCountsEachBinOnce) {
  EXPECT_DOUBLE_EQ(kld_needed(1, 0.05, 2.33), 1.0);
  double last = 1.0;
  for (int k = 2; k < 2000; k *= 2) {
    const double n = kld_needed(k, 0.05, 2.33);
    EXPECT_GT(n, last);
    last = n;
  }
  // Fox 2003: about 10 k / 2 epsilon for many bins at 99 %: 100 bins, epsilon 0.05 -> ~1,300.
  EXPECT_NEAR(kld_needed(100, 0.05, 2.33), 1300.0, 150.0);
  KldBins bins(8);
  EXPECT_TRUE(bins.insert(0, 0, 0));
  EXPECT_FALSE(bins.insert(0, 0, 0));
  EXPECT_TRUE(bins.insert(-1, 0, 0));
  EXPECT_TRUE(bins.insert(0, -1, 3));
  EXPECT_EQ(bins.size(), 3);
  for (int i = 0; i < 20; ++i) bins.insert(i, i, i);
  EXPECT_EQ(bins.size(), 8);  // full: nothing more is kept
  bins.clear();
  EXPECT_EQ(bins.size(), 0);
  EXPECT_TRUE(bins.insert(0, 0, 0));
  // Counting (the estimate's cluster cells).
  KldBins cells(4);
  EXPECT_EQ(cells.add(2, -3, 0), 1);
  EXPECT_EQ(cells.add(2, -3, 0), 2);
  EXPECT_EQ(cells.add(-2, 3, 0), 1);
  EXPECT_EQ(cells.count(2, -3, 0), 2);
  EXPECT_EQ(cells.count(5, 5, 0), 0);
  cells.add(7, 0, 0);
  cells.add(8, 0, 0);
  EXPECT_EQ(cells.add(9, 0, 0), 0);  // full: not counted
  EXPECT_EQ(cells.add(8, 0, 0), 2);  // an existing bin still counts
  cells.clear();
  EXPECT_EQ(cells.count(2, -3, 0), 0);
  EXPECT_EQ(cells.add(2, -3, 0), 1);
}

}  // namespace
}  // namespace robuter::loc

#include "tests/localise/lab_tour.hpp"

namespace robuter::loc {
namespace {

// The ring's 24 readings, made up (every fourth a silence when `silences`).
std::vector<SonarReading> made_up_readings(bool silences) {
  std::vector<SonarReading> readings(24);
  for (std::size_t i = 0; i < readings.size(); ++i)
    readings[i] = SonarReading{Eigen::Vector2d(0.3, 0.1), 0.26 * static_cast<double>(i), 0.5 + 0.15 * static_cast<double>(i),
                               silences && i % 4 == 3};
  return readings;
}

// A global search on the lab stepped `steps` times whole and, from the same seed, in parts by
// `weigh(filter, step)` (which calls weigh_some() until the step is done): the same particles
// after every step, the same averages at the end.
template <class Weigh>
void expect_parts_give_the_whole_step(std::uint64_t seed, const std::vector<SonarReading>& readings, int steps, Weigh weigh) {
  const auto lab = test::load_lab("default.toml");
  ParticleFilter whole(lab.field, FilterParams{}, seed), sliced(lab.field, FilterParams{}, seed);
  whole.set_global();
  sliced.set_global();
  whole.step(Pose(0, 0, 0), readings);
  sliced.step(Pose(0, 0, 0), readings);
  for (int k = 1; k <= steps; ++k) {
    const Pose odo(0.15 * k, 0.02 * k, 0.05 * k);
    ASSERT_TRUE(whole.step(odo, readings));
    ASSERT_TRUE(sliced.begin_step(odo, readings));
    EXPECT_FALSE(sliced.begin_step(odo + Pose(1, 0, 0), readings));  // one step at a time
    weigh(sliced, k);
    EXPECT_FALSE(sliced.stepping());
    ASSERT_EQ(whole.particles().size(), sliced.particles().size());
    for (std::size_t i = 0; i < whole.particles().size(); ++i)
      ASSERT_EQ(whole.particles()[i].pose, sliced.particles()[i].pose) << "step " << k << " particle " << i;
  }
  EXPECT_EQ(whole.w_fast(), sliced.w_fast());
  EXPECT_EQ(whole.w_slow(), sliced.w_slow());
}

TEST(ParticleFilterSlices, AStepInSlicesGivesTheWholeStepsParticles) {
  expect_parts_give_the_whole_step(11, made_up_readings(false), 6, [](ParticleFilter& f, int) {
    int parts = 1;
    while (!f.weigh_some(37)) ++parts;
    EXPECT_GT(parts, 1);
  });
}

// Why: the module's longest activation (issue #18: < 2 ms). A global search's particles each
// trace the map's promises (no two share a cell), a tracking cloud's mostly share them: 200
// particles a slice cost 3.3-3.6 ms in a global search. A slice now also ends once it has traced
// `traces` of them — and the step's particles are still the whole step's.
TEST(ParticleFilterSlices, ASliceEndsOnceItHasTracedItsBudgetOfPromises) {
  expect_parts_give_the_whole_step(12, made_up_readings(true), 4, [](ParticleFilter& f, int step) {
    int parts = 0, most = 0;
    for (bool done = false; !done; ++parts) {
      const int before = f.traced();
      done = f.weigh_some(200, 25);
      most = std::max(most, f.traced() - before);
    }
    EXPECT_LE(most, 25) << "step " << step;
    if (step == 1) {
      EXPECT_GT(parts, 2000 / 200);  // the global cloud's 2,000: the budget ended slices early
    }
  });
  // One particle a call at least: a budget of none still ends the step.
  const auto lab = test::load_lab("default.toml");
  ParticleFilter f(lab.field, FilterParams{}, 12);
  f.set_global();
  const auto readings = made_up_readings(true);
  f.step(Pose(0, 0, 0), readings);
  ASSERT_TRUE(f.begin_step(Pose(1.0, 0.1, 0.3), readings));
  int calls = 1;
  while (!f.weigh_some(200, 0)) ++calls;
  EXPECT_EQ(calls, f.weighed());
}

}  // namespace
}  // namespace robuter::loc
