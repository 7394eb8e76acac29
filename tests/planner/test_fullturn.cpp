// SPDX-License-Identifier: GPL-3.0-or-later
// The rectangle planner's footprint at every heading of the full turn, against an exact
// polygon-overlap test: the Robuter's body centre is 182.5 mm ahead of the axle (the pose), so
// the body is not symmetric under a half turn; the slices span the full turn and a (cell, slice)
// may be free only if the body, placed from the robot model, clears at every heading of it.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdlib>
#include <random>
#include <span>
#include <vector>

#include "modules/planner/lib/footprint.hpp"
#include "modules/planner/lib/planner.hpp"
#include "modules/planner/lib/thesis_files.hpp"
#include "robot/robot_model.hpp"
#include "tests/support/sample.hpp"

namespace robuter::plan {
namespace {

using Vec = Eigen::Vector2d;
using Quad = std::array<Vec, 4>;

// The body as the robot model states it (axle at the origin, x forward), grown by `margin`,
// placed at an axle pose: its four corners, counter-clockwise.
Quad body_at(const robot::Body& b, double margin, Vec axle, double heading) {
  const Eigen::Rotation2Dd r(heading);
  const double front = b.axle_to_front + margin, rear = -(b.axle_to_rear() + margin);
  const double half = 0.5 * b.width + margin;
  return {axle + r * Vec(front, -half), axle + r * Vec(front, half), axle + r * Vec(rear, half),
          axle + r * Vec(rear, -half)};
}

// A map cell's square.
Quad cell_square(const OccupancyMap& map, Cell c) {
  const Point2 o = map.center(c);
  const double h = 0.5 * map.resolution();
  return {Vec(o.x - h, o.y - h), Vec(o.x + h, o.y - h), Vec(o.x + h, o.y + h), Vec(o.x - h, o.y + h)};
}

// Exact overlap (with positive area) of two convex polygons: separating axes, the normals of
// both polygons' edges; touching is not overlapping.
bool overlap(const Quad& p, const Quad& q) {
  for (const Quad* poly : {&p, &q})
    for (std::size_t i = 0; i < 4; ++i) {
      const Vec e = (*poly)[(i + 1) % 4] - (*poly)[i];
      const Vec n(-e.y(), e.x());
      double plo = n.dot(p[0]), phi = plo, qlo = n.dot(q[0]), qhi = qlo;
      for (std::size_t j = 1; j < 4; ++j) {
        plo = std::min(plo, n.dot(p[j]));
        phi = std::max(phi, n.dot(p[j]));
        qlo = std::min(qlo, n.dot(q[j]));
        qhi = std::max(qhi, n.dot(q[j]));
      }
      if (phi <= qlo || qhi <= plo) return false;
    }
  return true;
}

// The exact verdict: the body at the pose meets an occupied cell of the map.
bool exact_blocked(const OccupancyMap& map, std::span<const Cell> occupied, const robot::Body& b,
                   double margin, Vec axle, double heading) {
  const Quad body = body_at(b, margin, axle, heading);
  const double reach = b.corner_radius() + margin + map.resolution();
  for (const Cell c : occupied) {
    const Point2 o = map.center(c);
    if ((Vec(o.x, o.y) - axle).norm() > reach) continue;
    if (overlap(body, cell_square(map, c))) return true;
  }
  return false;
}

PlannerConfig robuter_config(double margin, int slices) {
  const robot::Body& b = robot::kRobuter.body;
  PlannerConfig c;
  c.footprint = FootprintKind::Rectangle;
  c.rectangle = RectangleFootprint{b.length, b.width, b.center_ahead(), margin};
  c.heading_slices = slices;
  return c;
}

// The planner's verdict for the robot's axle at a cell's centre, at any heading.
bool planner_blocked(const Planner& p, Cell c, double heading) {
  return p.expanded(slice_of_heading(heading, p.slices())).at(c) == kBlocked;
}

// A 4 x 4 m free room at 5 cm with a wall filling every cell on one side of a face.
enum class Side { West, East, South, North };
OccupancyMap wall_map(Side side, double face) {
  OccupancyMap m(MapGeometry{80, 80, 0.05, {}});
  for (int y = 0; y < 80; ++y)
    for (int x = 0; x < 80; ++x) {
      const Point2 o = m.center({x, y});
      const bool wall = side == Side::West ? o.x < face : side == Side::East ? o.x > face
                        : side == Side::South ? o.y < face : o.y > face;
      if (wall) m.mark_occupied({x, y});
      else m.mark_free({x, y});
    }
  m.clear_changes();
  return m;
}

std::vector<Cell> occupied_cells(const OccupancyMap& m) {
  std::vector<Cell> out;
  for (int y = 0; y < m.height(); ++y)
    for (int x = 0; x < m.width(); ++x)
      if (m.state({x, y}) == CellState::Occupied) out.push_back({x, y});
  return out;
}

struct WallCase {
  Side side;         // where the wall is
  double face;       // m, the wall face's x (West, East) or y (South, North)
  Point2 axle;       // m, a cell centre 0.525 m from the face
  double to_wall;    // rad, the heading that faces the wall
};

// The case and its mirrors: the axle 0.525 m from a wall face, the body's front (0.695 m
// ahead of the axle) 0.17 m into the wall when facing it, its rear (0.330 m behind) 0.195 m clear
// when the back is turned.
const WallCase kWallCases[] = {
    {Side::West, 1.0, {1.525, 2.025}, kPi},           // facing west: slice 0 (was free)
    {Side::East, 3.0, {2.475, 2.025}, 0.0},           // facing east
    {Side::South, 1.0, {2.025, 1.525}, -kPi / 2},     // facing south: slice K/2 (was free)
    {Side::North, 3.0, {2.025, 2.475}, kPi / 2},      // facing north
};

void expect_wall_case(const WallCase& w) {
  const OccupancyMap map = wall_map(w.side, w.face);
  const std::vector<Cell> occ = occupied_cells(map);
  Planner p(robuter_config(0.0, 16));
  p.set_map(map);
  const Cell c = map.cell_of(w.axle);
  ASSERT_NEAR(map.center(c).x, w.axle.x, 1e-9);
  ASSERT_NEAR(map.center(c).y, w.axle.y, 1e-9);
  const robot::Body& b = robot::kRobuter.body;
  // Facing the wall: the exact test and the planner both say blocked, at every heading of the slice.
  EXPECT_TRUE(exact_blocked(map, occ, b, 0.0, {w.axle.x, w.axle.y}, w.to_wall));
  EXPECT_TRUE(planner_blocked(p, c, w.to_wall));
  // The back to the wall: the body clears it, and the full-turn slice a half turn away says so.
  EXPECT_FALSE(exact_blocked(map, occ, b, 0.0, {w.axle.x, w.axle.y}, w.to_wall + kPi));
  EXPECT_FALSE(planner_blocked(p, c, w.to_wall + kPi));
  EXPECT_NE(slice_of_heading(w.to_wall, p.slices()), slice_of_heading(w.to_wall + kPi, p.slices()));
  // 0.80 m from the face, the front (0.726 m ahead at a slice's edge) clears: free both ways.
  const double back = 0.80 - 0.525;
  const Point2 far{w.axle.x - back * std::cos(w.to_wall), w.axle.y - back * std::sin(w.to_wall)};
  const Cell fc = map.cell_of(far);
  EXPECT_FALSE(planner_blocked(p, fc, w.to_wall));
  EXPECT_FALSE(planner_blocked(p, fc, w.to_wall + kPi));
}

TEST(FullTurnFootprint, AxleEastOfAWallFacingWestIsBlocked) { expect_wall_case(kWallCases[0]); }
TEST(FullTurnFootprint, AxleWestOfAWallFacingEastIsBlocked) { expect_wall_case(kWallCases[1]); }
TEST(FullTurnFootprint, AxleNorthOfAWallFacingSouthIsBlocked) { expect_wall_case(kWallCases[2]); }
TEST(FullTurnFootprint, AxleSouthOfAWallFacingNorthIsBlocked) { expect_wall_case(kWallCases[3]); }

// Legs may be driven backwards: the robot then faces the slice's heading while moving the other
// way. Every waypoint of a plan through a door (and past walls) must clear the exact test with
// the body where it really is, at the waypoint's (full-turn) slice heading.
TEST(FullTurnFootprint, PlannedPathClearsWithTheBodyWhereItIs) {
  OccupancyMap m(MapGeometry{120, 80, 0.05, {}});
  for (int y = 0; y < 80; ++y)
    for (int x = 0; x < 120; ++x) m.mark_free({x, y});
  rasterise_polygons(m, {Polygon{{{0.0, 2.0}, {2.5, 2.0}, {2.5, 2.1}, {0.0, 2.1}}},
                         Polygon{{{3.45, 2.0}, {6.0, 2.0}, {6.0, 2.1}, {3.45, 2.1}}},
                         Polygon{{{0.0, 0.0}, {6.0, 0.0}, {6.0, 0.05}, {0.0, 0.05}}},
                         Polygon{{{0.0, 3.95}, {6.0, 3.95}, {6.0, 4.0}, {0.0, 4.0}}}});
  m.clear_changes();
  const std::vector<Cell> occ = occupied_cells(m);
  const robot::Body& b = robot::kRobuter.body;
  for (MotionModel motion : {MotionModel::Aligned, MotionModel::Holonomic}) {
    PlannerConfig cfg = robuter_config(0.0, 16);
    cfg.motion = motion;
    Planner p(cfg);
    p.set_map(m);
    const PlanResult r = p.plan({1.0, 0.9, 0.0}, {5.0, 3.1});
    ASSERT_TRUE(r.found()) << to_string(r.status);
    ASSERT_FALSE(p.waypoints().empty());
    for (const Waypoint& w : p.waypoints())
      EXPECT_FALSE(exact_blocked(m, occ, b, 0.0, {w.pose.x, w.pose.y}, w.pose.heading))
          << "waypoint " << w.pose.x << "," << w.pose.y << " heading " << w.pose.heading;
  }
}

// Why: the sample size; ROBUTER_FOOTPRINT_POSES (make bench: 100000) overrides.
int pose_count() {
  if (const char* env = std::getenv("ROBUTER_FOOTPRINT_POSES")) return std::max(1, std::atoi(env));
  return ::robuter::test::sample(10'000, 2'000);
}

// The property: on random maps (random obstacles, resolution, margin and slice count), at random
// cells and headings over the full turn, the planner never calls free a pose the exact test
// calls blocked.
TEST(FullTurnFootprint, NeverFreeWhereTheExactTestIsBlocked) {
  const int poses = pose_count();
  constexpr int kPosesPerMap = 100;
  std::mt19937 rng(16);
  const robot::Body& b = robot::kRobuter.body;
  struct Variant {
    double resolution;
    double margin;
    int slices;
  };
  const Variant variants[] = {{0.05, 0.0, 16}, {0.05, 0.03, 16}, {0.05, 0.0, 8},
                              {0.10, 0.0, 16}, {0.04, 0.0, 24}, {0.05, 0.0, 12}};
  std::vector<Planner> planners;
  planners.reserve(std::size(variants));
  for (const Variant& v : variants) planners.emplace_back(robuter_config(v.margin, v.slices));
  std::uniform_int_distribution<std::size_t> pick_variant(0, std::size(variants) - 1);
  std::uniform_real_distribution<double> density(0.0002, 0.008), heading(-kPi, kPi), unit(0.0, 1.0);
  long blocked = 0, free_ok = 0, conservative = 0, unsound = 0;
  for (int done = 0; done < poses;) {
    const std::size_t vi = pick_variant(rng);
    const Variant& v = variants[vi];
    const int side = static_cast<int>(std::lround(2.6 / v.resolution));
    OccupancyMap map(MapGeometry{side, side, v.resolution, {-1.3, -0.7}});
    const double d = density(rng);
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x) {
        if (unit(rng) < d) map.mark_occupied({x, y});
        else map.mark_free({x, y});
      }
    map.clear_changes();
    const std::vector<Cell> occ = occupied_cells(map);
    Planner& p = planners[vi];
    p.set_map(map);
    std::uniform_int_distribution<int> coord(0, side - 1);
    for (int k = 0; k < kPosesPerMap && done < poses; ++k, ++done) {
      const Cell c{coord(rng), coord(rng)};
      const double th = heading(rng);
      const Point2 o = map.center(c);
      const bool exact = exact_blocked(map, occ, b, v.margin, {o.x, o.y}, th);
      const bool plan = planner_blocked(p, c, th);
      if (exact) ++blocked;
      if (exact && !plan) {
        ++unsound;
        ADD_FAILURE() << "free in the planner, blocked exactly: cell " << c.x << "," << c.y << " heading "
                      << th << " resolution " << v.resolution << " margin " << v.margin << " slices "
                      << v.slices;
      }
      if (!exact && plan) ++conservative;
      if (!exact && !plan) ++free_ok;
      if (unsound > 10) return;
    }
  }
  std::printf("%d poses: %ld blocked exactly, %ld free in both, %ld blocked by the planner only "
              "(the slice's sweep, whole cells), %ld unsound\n",
              poses, blocked, free_ok, conservative, unsound);
  EXPECT_GT(blocked, poses / 10);  // the sample exercises both verdicts
  EXPECT_GT(free_ok, poses / 10);
  EXPECT_EQ(unsound, 0);
}

}  // namespace
}  // namespace robuter::plan
