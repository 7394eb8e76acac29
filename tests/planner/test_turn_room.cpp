// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the turn measured from the robot's pose: the rounded grown body against the map's cells.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>

#include "modules/planner/lib/planner.hpp"
#include "modules/planner/lib/turn_room.hpp"
#include "robot/robot_model.hpp"

namespace robuter::plan {
namespace {

RectangleFootprint robuter_body() {
  const robot::Body& b = robot::kRobuter.body;
  return RectangleFootprint{b.length, b.width, b.center_ahead(), 0.0};
}

// A corridor running north, `width` m between its faces (on cell boundaries), 6 m long, its
// centre line at x = 3 m.
OccupancyMap corridor(double width) {
  OccupancyMap map(MapGeometry{120, 120, 0.05, {0.0, 0.0}});
  const int half = static_cast<int>(std::lround(0.5 * width / 0.05));
  for (int y = 0; y < 120; ++y)
    for (int k = 0; k < 3; ++k) {
      map.mark_occupied({60 - half - 1 - k, y});
      map.mark_occupied({60 + half + k, y});
    }
  return map;
}

PlannerConfig robuter_config(double turn_clearance) {
  PlannerConfig c;
  c.footprint = FootprintKind::Rectangle;
  c.rectangle = robuter_body();
  c.turn_clearance = turn_clearance;
  return c;
}

// Why: the least body-to-obstacle distance over a turn by brute force, every 0.05 degree (which
// overstates the least by at most 0.3 mm: a body point moves 0.778 m x 0.00044 rad between
// samples), up to kCap: a cell whose nearest point lies kCap beyond the body's reach, or whose
// distance sampled every degree stays kCap above it by more than a body point moves between
// those samples, is farther than kCap at every heading and is skipped (the tests ask about
// 0.25 and 0.30 m only).
constexpr double kCap = 0.31;  // m
double least_distance(const OccupancyMap& map, const RectangleFootprint& body, const Pose2& pose, double target) {
  const double reach = std::hypot(0.5 * body.length + std::abs(body.center_offset), 0.5 * body.width);
  const double span = std::abs(target - pose.heading);
  const auto sampled = [&](Cell c, double step_deg) {
    const int steps = std::max(1, static_cast<int>(std::ceil(span / (step_deg * kPi / 180.0))));
    double d = 1e9;
    for (int i = 0; i <= steps; ++i)
      d = std::min(d, body_cell_distance(map, body, {pose.x, pose.y, pose.heading + (target - pose.heading) * i / steps}, c));
    return d;
  };
  double least = kCap;
  const double r = map.resolution();
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x) {
      if (map.state({x, y}) != CellState::Occupied) continue;
      const Point2 m = map.center({x, y});
      const double nx = std::clamp(pose.x, m.x - 0.5 * r, m.x + 0.5 * r), ny = std::clamp(pose.y, m.y - 0.5 * r, m.y + 0.5 * r);
      if (std::hypot(nx - pose.x, ny - pose.y) >= reach + kCap) continue;
      if (sampled({x, y}, 1.0) - reach * 0.5 * (kPi / 180.0) > kCap) continue;
      least = std::min(least, sampled({x, y}, 0.05));
    }
  return least;
}

TEST(TurnRoom, TheGrownBodysRadiusPeaksAtItsCorners) {
  const RectangleFootprint body = robuter_body();
  const TurnEnvelope e(body, 0.25);
  const double front = 0.5 * body.length + body.center_offset;  // 0.695 m
  EXPECT_NEAR(e.reach(), std::hypot(front, 0.35) + 0.25, 1e-12);
  EXPECT_NEAR(e.radius(std::atan2(0.35, front)), std::hypot(front, 0.35) + 0.25, 1e-9);
  EXPECT_NEAR(e.radius(0.0), front + 0.25, 1e-9);                   // ahead: the front face
  EXPECT_NEAR(e.radius(kPi / 2), 0.35 + 0.25, 1e-9);                // aside
  EXPECT_NEAR(e.radius(kPi), (body.length - front) + 0.25, 1e-9);   // behind: the rear face
}

// The acceptance route corridor-b-4 -> room-03 starts across a 2.10 m corridor: the front
// corners turn on 0.778 m, 0.272 m from each face at the centre line. The layers (square-grown
// by 0.25 m, cells) forbid that turn; measured from the pose it keeps its 0.25 m.
TEST(TurnRoom, AcrossA210mCorridorTheTurnKeepsItsClearance) {
  const OccupancyMap map = corridor(2.10);
  Planner p(robuter_config(0.25));
  p.set_map(map);
  const Pose2 centre{3.0, 3.0, 0.0};
  EXPECT_TRUE(p.can_turn_at(centre, kPi));         // to face the other way
  EXPECT_TRUE(p.can_turn_at(centre, -kPi / 2));    // to go south
  EXPECT_TRUE(p.can_turn_at(centre, 2.0 * kPi));   // a full turn (exploring)
  EXPECT_GE(least_distance(map, robuter_body(), centre, 2.0 * kPi), 0.25);
  int refused = 0;  // the layers' rule at the same place
  for (int k = 0; k < p.slices(); ++k) refused += p.can_turn(map.cell_of({3.0, 3.0}), k) ? 0 : 1;
  EXPECT_GT(refused, 0);
  // 2 cm off the centre line a front corner passes 0.252 m from a face; 3 cm off, 0.242 m: refused.
  EXPECT_TRUE(p.can_turn_at({3.02, 3.0, 0.0}, kPi));
  EXPECT_FALSE(p.can_turn_at({3.03, 3.0, 0.0}, kPi));
  EXPECT_FALSE(p.can_turn_at({2.97, 3.0, 0.0}, kPi));
}

TEST(TurnRoom, A2mCorridorIsTooNarrowAndAShortTurnNeedsLessRoom) {
  const OccupancyMap map = corridor(2.00);
  Planner p(robuter_config(0.25));
  p.set_map(map);
  EXPECT_FALSE(p.can_turn_at({3.0, 3.0, kPi / 2}, -kPi / 2));  // facing north, round to south
  // A few degrees either side of north: the front corners stay well inside the faces.
  EXPECT_TRUE(p.can_turn_at({3.0, 3.0, kPi / 2 - 0.1}, kPi / 2 + 0.1));
}

TEST(TurnRoom, RefusesOffTheMapTheAxlesCellAndNonFinitePoses) {
  OccupancyMap map(MapGeometry{60, 60, 0.05, {0.0, 0.0}});
  Planner p(robuter_config(0.25));
  p.set_map(map);
  EXPECT_TRUE(p.can_turn_at({1.5, 1.5, 0.0}, kPi));
  EXPECT_FALSE(p.can_turn_at({-1.0, 1.5, 0.0}, kPi));
  EXPECT_FALSE(p.can_turn_at({1.5, 1.5, std::nan("")}, kPi));
  EXPECT_FALSE(p.can_turn_at({1.5, 1.5, 0.0}, std::numeric_limits<double>::infinity()));
  map.mark_occupied(map.cell_of({1.5, 1.5}));
  p.set_map(map);
  EXPECT_FALSE(p.can_turn_at({1.5, 1.5, 0.0}, 0.01));
}

// Random obstacles near the robot, random turns: a turn allowed keeps the clearance by brute
// force (never unsafe), and a turn with a cell's width to spare is allowed (not needlessly strict).
TEST(TurnRoom, NeverAllowsATurnThatComesCloserAndRarelyRefusesOneWithRoomToSpare) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const RectangleFootprint body = robuter_body();
  const TurnEnvelope e(body, 0.25);
  int allowed = 0, spare = 0, spare_refused = 0;
  for (int run = 0; run < 600; ++run) {
    OccupancyMap map(MapGeometry{60, 60, 0.05, {0.0, 0.0}});
    const int n = 1 + static_cast<int>(u(rng) * 6);
    for (int k = 0; k < n; ++k) {
      const double r = 0.6 + 0.6 * u(rng), a = 2.0 * kPi * u(rng);
      map.mark_occupied(map.cell_of({1.5 + r * std::cos(a), 1.5 + r * std::sin(a)}));
    }
    const Pose2 pose{1.5 + 0.05 * u(rng), 1.5 + 0.05 * u(rng), 2.0 * kPi * u(rng)};
    const double target = pose.heading + (u(rng) - 0.5) * 2.5 * kPi;
    const bool ok = e.turn_is_clear(map, pose, target);
    const double least = least_distance(map, body, pose, target);
    if (ok) {
      ++allowed;
      EXPECT_GT(least, 0.25 - 1e-6) << "run " << run;
    }
    if (least > 0.25 + 0.05) {
      ++spare;
      spare_refused += ok ? 0 : 1;
    }
  }
  EXPECT_GT(allowed, 50);
  EXPECT_GT(spare, 40);
  EXPECT_EQ(spare_refused, 0);
}

// Why: a figure, not a test of time: the cost of a costly turn asked (a half turn with a wall
// 0.75 m beside the axle, three rows of cells within reach the whole turn), printed for the docs.
TEST(TurnRoom, CostOfAHalfTurnBesideAWall) {
  OccupancyMap map(MapGeometry{60, 60, 0.05, {0.0, 0.0}});
  for (int x = 0; x < 60; ++x)
    for (int y = 12; y < 15; ++y) map.mark_occupied({x, y});  // the face at y = 0.75 m
  const TurnEnvelope e(robuter_body(), 0.25);
  const Pose2 pose{1.5, 1.5, 0.0};
  // Counter-clockwise from east to west: the rear corners (0.48 m, 0.73 m grown) sweep past the
  // wall, the front corners swing away from it.
  EXPECT_GT(least_distance(map, robuter_body(), pose, kPi), 0.25);
  bool ok = false;
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < 100; ++k) ok = e.turn_is_clear(map, pose, kPi);
  const auto t1 = std::chrono::steady_clock::now();
  EXPECT_TRUE(ok);
  EXPECT_FALSE(e.turn_is_clear(map, pose, -kPi));  // clockwise, a front corner passes over the wall
  std::printf("half turn beside a wall: %.1f us per check\n",
              std::chrono::duration<double, std::micro>(t1 - t0).count() / 100);
}

}  // namespace
}  // namespace robuter::plan
