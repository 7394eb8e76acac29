// SPDX-License-Identifier: GPL-3.0-or-later
// The distance field against brute force, and its queries outside the grid.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "modules/localise/lib/distance_field.hpp"

namespace robuter::loc {
namespace {

TEST(DistanceField, EqualsTheNearestOccupiedCellOnRandomGrids) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 40; ++trial) {
    FieldGeometry g;
    g.width = 5 + static_cast<int>(rng() % 40);
    g.height = 5 + static_cast<int>(rng() % 40);
    g.resolution = 0.05;
    g.origin = Eigen::Vector2d(-1.0, 2.0);
    const double density = (trial % 4 == 0) ? 0.002 : 0.05 * (1 + trial % 3);
    std::vector<std::uint8_t> occ(static_cast<std::size_t>(g.width * g.height));
    std::bernoulli_distribution b(density);
    for (auto& c : occ) c = b(rng) ? 1 : 0;
    const double cap = 0.8;
    const DistanceField f(g, occ, cap);
    for (int y = 0; y < g.height; ++y)
      for (int x = 0; x < g.width; ++x) {
        double best = cap;
        for (int v = 0; v < g.height; ++v)
          for (int u = 0; u < g.width; ++u)
            if (occ[static_cast<std::size_t>(v * g.width + u)])
              best = std::min(best, std::hypot(u - x, v - y) * g.resolution);
        ASSERT_NEAR(f.cell(x, y), best, 1e-5) << "trial " << trial << " cell " << x << "," << y;
        ASSERT_NEAR(f.at(f.center(x, y)), best, 1e-5);
      }
  }
}

TEST(DistanceField, OutsideTheGridIsFarAndAnEmptyOrMisSizedGridHoldsNothing) {
  FieldGeometry g{4, 3, 0.1, Eigen::Vector2d(0.0, 0.0)};
  std::vector<std::uint8_t> occ(12, 0);
  occ[5] = 1;
  const DistanceField f(g, occ, 2.0);
  EXPECT_DOUBLE_EQ(f.at(Eigen::Vector2d(-0.01, 0.1)), 2.0);
  EXPECT_DOUBLE_EQ(f.at(Eigen::Vector2d(0.1, 0.31)), 2.0);
  EXPECT_NEAR(f.at(Eigen::Vector2d(0.15, 0.15)), 0.0, 1e-9);
  EXPECT_TRUE(DistanceField(g, std::vector<std::uint8_t>(11, 0), 2.0).empty());
  // Nothing occupied: every cell at the cap.
  const DistanceField none(g, std::vector<std::uint8_t>(12, 0), 1.5);
  EXPECT_DOUBLE_EQ(none.cell(2, 1), 1.5);
}

}  // namespace
}  // namespace robuter::loc
