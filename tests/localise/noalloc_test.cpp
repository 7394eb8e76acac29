// SPDX-License-Identifier: GPL-3.0-or-later
// The filter's steps allocate nothing once it is built (normal build: the sanitizers own malloc).
#include <gtest/gtest.h>

#include <vector>

#include "tests/localise/lab_tour.hpp"
#include "tests/support/alloc_counter.hpp"

namespace robuter::loc {
namespace {

TEST(LocaliseNoAlloc, StepsAfterConstructionAllocateNothing) {
  const auto lab = test::load_lab("default.toml");
  FilterParams params;
  ParticleFilter filter(lab.field, params, 5);
  filter.set_global();  // the most particles, every one weighed
  std::vector<SonarReading> readings(24);
  for (std::size_t i = 0; i < readings.size(); ++i)
    readings[i] = SonarReading{Eigen::Vector2d(0.3, 0.0), 0.26 * static_cast<double>(i), 0.4 + 0.1 * static_cast<double>(i)};
  filter.step(Pose(0, 0, 0), readings);
  robuter::test::AllocCounter counter;
  int stepped = 0;
  for (int k = 1; k <= 50; ++k) stepped += filter.step(Pose(0.12 * k, 0.0, 0.02 * k), readings) ? 1 : 0;
  filter.set_pose(Pose(2.0, 2.0, 0.0), Eigen::Vector3d(0.1, 0.1, 0.1));
  stepped += filter.step(Pose(7.0, 0.0, 0.0), readings) ? 1 : 0;
  filter.set_global();
  if (filter.begin_step(Pose(8.0, 0.0, 0.0), readings)) {  // in slices, as the module will
    while (!filter.weigh_some(100)) {}
    ++stepped;
  }
  const auto e = filter.estimate();
  const auto allocations = counter.count();
  EXPECT_EQ(stepped, 52);
  EXPECT_GT(e.particles, 0);
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace robuter::loc
