// SPDX-License-Identifier: GPL-3.0-or-later
// The planner module's pure parts: ring beams and body in the map, the window, prefix, legs, follower.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "modules/planner/lib/text_render.hpp"
#include "modules/planner/map_window.hpp"
#include "modules/planner/path_follower.hpp"
#include "modules/planner/picture_mailbox.hpp"
#include "modules/planner/route.hpp"
#include "modules/planner/sonar_mapping.hpp"
#include "robot/robot_model.hpp"

namespace robuter::planner {
namespace {

plan::OccupancyMap small_map() { return plan::OccupancyMap(plan::MapGeometry{100, 100, 0.05, {0.0, 0.0}}, 2); }

TEST(RingGeometry, SensorOneLooksForwardAndNumbersRunClockwise) {
  const auto mount = [](int s) { return robot::kRobuter.ring.sensor(s).mount; };
  EXPECT_DOUBLE_EQ(mount(1).direction, 0.0);
  EXPECT_NEAR(mount(7).direction, -plan::kPi / 2, 1e-12);   // sensor 7: right
  EXPECT_NEAR(std::abs(mount(13).direction), plan::kPi, 1e-12);  // sensor 13: rear
  EXPECT_NEAR(mount(19).direction, plan::kPi / 2, 1e-12);   // sensor 19: left
  for (int s = 1; s <= robot::kRingSensors; ++s) {  // on the body: x in [-0.33, 0.695], |y| <= 0.35
    EXPECT_GE(mount(s).x, -0.3301);
    EXPECT_LE(mount(s).x, 0.6951);
    EXPECT_LE(std::abs(mount(s).y), 0.3501);
  }
}

TEST(SonarMapping, AnEchoMarksItsCellAndClearsTheWayThere) {
  plan::OccupancyMap map = small_map();
  const plan::Pose2 robot{1.0, 2.5, 0.0};
  const SensorMount front = robot::kRobuter.ring.sensor(1).mount;  // 0.695 m ahead, looking forward
  for (int i = 0; i < 2; ++i) integrate_reading(map, robot, front, 1.0, false, 2.5, 0.0);
  const plan::Cell hit = map.cell_of({1.0 + 0.695 + 1.0, 2.5});
  EXPECT_EQ(map.state(hit), plan::CellState::Occupied);
  EXPECT_EQ(map.state({hit.x - 5, hit.y}), plan::CellState::Free);
  EXPECT_EQ(map.state({hit.x + 2, hit.y}), plan::CellState::Unknown);
  // Far or absent echoes only clear, and only up to the beam range.
  plan::OccupancyMap m2 = small_map();
  integrate_reading(m2, robot, front, 4.95, true, 1.0, 0.2);
  EXPECT_EQ(m2.state(m2.cell_of({1.695 + 0.9, 2.5})), plan::CellState::Free);
  EXPECT_EQ(m2.state(m2.cell_of({1.695 + 1.2, 2.5})), plan::CellState::Unknown);
  integrate_reading(m2, robot, front, 0.0, false, 1.0, 0.2);  // no data: nothing
}

// The pan-tilt's transducer sits on its beam, `face` from the pan axis; the robot's heading at
// the firing turns everything.
TEST(SonarMapping, APanTiltReadingMarksFromItsTransducerFace) {
  const SensorMount ahead = pan_tilt_mount(robot::PanTiltMount{-0.03, 0.05}, 0.0);
  EXPECT_NEAR(ahead.x, 0.02, 1e-12);
  EXPECT_NEAR(ahead.y, 0.0, 1e-12);
  const SensorMount left = pan_tilt_mount(robot::PanTiltMount{-0.03, 0.05}, plan::kPi / 2);
  EXPECT_NEAR(left.x, -0.03, 1e-12);
  EXPECT_NEAR(left.y, 0.05, 1e-12);
  EXPECT_NEAR(left.direction, plan::kPi / 2, 1e-12);
  plan::OccupancyMap map = small_map();
  const plan::Pose2 fired{2.5, 2.5, plan::kPi / 2};  // the robot faces +y: "left" looks along -x
  for (int i = 0; i < 2; ++i) integrate_reading(map, fired, left, 1.2, false, 2.5, 0.0);
  const plan::Cell hit = map.cell_of({2.5 - 0.05 - 1.2, 2.5 - 0.03});
  EXPECT_EQ(map.state(hit), plan::CellState::Occupied);
  EXPECT_EQ(map.state({hit.x + 6, hit.y}), plan::CellState::Free);
}

TEST(SonarMapping, AnEchoGoesToTheArcCellThatLooksMostLikeAnObstacle) {
  const plan::Pose2 robot{1.0, 2.5, 0.0};
  const SensorMount front = robot::kRobuter.ring.sensor(1).mount;
  const double cone = 12.5 * plan::kPi / 180.0;
  // Nothing known: the axis (seed 003).
  plan::OccupancyMap map = small_map();
  integrate_reading(map, robot, front, 1.0, false, 2.5, cone);
  EXPECT_EQ(map.count(map.cell_of({2.695, 2.5})), 1);
  // A wall known 0.15 m to the left of the axis at the echo's range, the axis seen free: the
  // echo came from the wall (a jamb at the cone's edge), the doorway on the axis stays free.
  plan::OccupancyMap door = small_map();
  const plan::Point2 jamb{1.695 + 1.0 * std::cos(0.15), 2.5 + 1.0 * std::sin(0.15)};
  door.set_count(door.cell_of(jamb), 3);
  door.mark_free(door.cell_of({2.695, 2.5}));
  integrate_reading(door, robot, front, 1.0, false, 2.5, cone);
  EXPECT_EQ(door.count(door.cell_of(jamb)), 4);
  EXPECT_EQ(door.count(door.cell_of({2.695, 2.5})), 0);
  EXPECT_EQ(door.state(door.cell_of({2.3, 2.5})), plan::CellState::Free);  // the axis is cleared
}

TEST(SonarMapping, TheBodysCellsAreFree) {
  plan::OccupancyMap map = small_map();
  const plan::Pose2 robot{2.0, 2.0, plan::kPi / 2};
  map.mark_occupied(map.cell_of({2.0, 2.3}));  // under the body (body centre 0.18 m ahead)
  map.mark_occupied(map.cell_of({2.0, 3.2}));  // beyond its front (0.695 m ahead)
  mark_body_free(map, robot, robot::Body{1.025, 0.7, 0.695});  // centre 0.1825 m ahead
  EXPECT_EQ(map.state(map.cell_of({2.0, 2.3})), plan::CellState::Free);
  EXPECT_EQ(map.state(map.cell_of({2.0, 3.2})), plan::CellState::Occupied);
  EXPECT_EQ(map.state(map.cell_of({2.0, 1.5})), plan::CellState::Unknown);  // not under it: unknown
}

TEST(MapWindow, SameCharactersAsTheLibrarysTextView) {
  plan::OccupancyMap map = small_map();
  map.mark_occupied({12, 14});
  map.mark_free({10, 11});
  std::vector<char> out(7 * 7);
  render_window(map, {10, 10}, 7, out);
  const std::string text = plan::render_around(map, {10, 10}, 3);
  std::string joined;
  for (int r = 0; r < 7; ++r) joined += std::string(out.data() + r * 7, 7) + "\n";
  EXPECT_EQ(joined, text);
  EXPECT_EQ(out[3 * 7 + 3], 'P');
  render_window(map, {0, 0}, 7, out);  // off the map: '.'
  EXPECT_EQ(out[0], '.');
}

// Waypoints of a hand-made rectangle path (K = 16: 32 slices over the full turn): cells and slices.
std::vector<plan::Waypoint> path_of(const plan::OccupancyMap& map, std::initializer_list<plan::CellPose> cells) {
  std::vector<plan::Waypoint> w;
  for (const plan::CellPose& c : cells) {
    const plan::Point2 p = map.center({c.x, c.y});
    w.push_back({c, {p.x, p.y, plan::slice_heading(c.slice, 32)}});
  }
  return w;
}

TEST(Route, StraightRunsMakeOneLegAndTurnsSetTheNextHeading) {
  const plan::OccupancyMap map = small_map();
  // East 3 cells, turn +4 slices (45°) in place, north-east 2 cells.
  const auto path = path_of(map, {{10, 10, 0}, {11, 10, 0}, {12, 10, 0}, {13, 10, 0}, {13, 10, 1}, {13, 10, 2},
                                  {13, 10, 3}, {13, 10, 4}, {14, 11, 4}, {15, 12, 4}});
  std::array<Leg, 8> legs{};
  std::size_t used = 0;
  const std::size_t n = build_legs(path, 0.02, 32, legs, used);
  ASSERT_EQ(n, 2u);
  EXPECT_EQ(used, path.size());
  EXPECT_TRUE(legs[0].forward);
  EXPECT_NEAR(legs[0].heading, 0.0, 1e-12);
  EXPECT_NEAR(legs[0].end.x, map.center({13, 10}).x, 1e-12);
  EXPECT_NEAR(legs[1].heading, plan::kPi / 4, 1e-12);
  EXPECT_TRUE(legs[1].forward);
  EXPECT_EQ(legs[1].first, 7u);
}

TEST(Route, TheLongWayRoundIsKept) {
  const plan::OccupancyMap map = small_map();
  // Clockwise by 12 slices (135°) from slice 0 to slice 20 (-135°), then along (+1, +1): the
  // robot faces -135° and backs north-east; it does not turn 45° counter-clockwise instead.
  std::vector<plan::CellPose> cells = {{10, 10, 0}};
  for (int k = 1; k <= 12; ++k) cells.push_back({10, 10, (32 - k) % 32});
  cells.push_back({11, 11, 20});
  std::vector<plan::Waypoint> path;
  for (const plan::CellPose& c : cells) {
    const plan::Point2 p = map.center({c.x, c.y});
    path.push_back({c, {p.x, p.y, plan::slice_heading(c.slice, 32)}});
  }
  std::array<Leg, 4> legs{};
  std::size_t used = 0;
  ASSERT_EQ(build_legs(path, 0.0, 32, legs, used), 1u);
  EXPECT_NEAR(legs[0].heading, -3 * plan::kPi / 4, 1e-12);
  EXPECT_FALSE(legs[0].forward);
}

TEST(Route, MovingAgainstTheHeadingIsBacking) {
  const plan::OccupancyMap map = small_map();
  const auto path = path_of(map, {{10, 10, 0}, {9, 10, 0}, {8, 10, 0}});  // west, slice 0 (heading 0)
  std::array<Leg, 4> legs{};
  std::size_t used = 0;
  ASSERT_EQ(build_legs(path, 0.0, 32, legs, used), 1u);
  EXPECT_FALSE(legs[0].forward);
  EXPECT_NEAR(legs[0].heading, 0.0, 1e-12);
  // A robot facing west (heading π) drives the same path forward.
  ASSERT_EQ(build_legs(path, plan::kPi, 32, legs, used), 1u);
  EXPECT_TRUE(legs[0].forward);
  EXPECT_NEAR(legs[0].heading, plan::kPi, 1e-12);
  // A disc always drives forward: it turns to face west.
  ASSERT_EQ(build_legs(path, 0.0, 0, legs, used), 1u);
  EXPECT_TRUE(legs[0].forward);
  EXPECT_NEAR(std::abs(legs[0].heading), plan::kPi, 1e-12);
}

TEST(Route, ThePrefixStopsAtTheSonarRangeAndAtWhatIsHidden) {
  plan::OccupancyMap map = small_map();
  std::vector<plan::Waypoint> path;
  for (int x = 10; x < 90; ++x) {
    const plan::Point2 p = map.center({x, 50});
    path.push_back({{x, 50, 0}, {p.x, p.y, 0.0}});
  }
  const plan::Point2 robot = map.center({10, 50});
  EXPECT_EQ(visible_prefix(map, path, robot, 1.5), 31u);  // 30 cells of 5 cm
  map.mark_occupied({12, 50});  // in the line of sight (the planner would not go through it)
  EXPECT_EQ(visible_prefix(map, path, robot, 1.5), 2u);
  EXPECT_NEAR(chain_length({path.data(), 31}), 1.5, 1e-9);
}

// Unicycle kinematics driven by the follower's wheel speeds, 100 ms steps.
plan::Pose2 drive(PathFollower& f, plan::Pose2 p, int steps) {
  for (int i = 0; i < steps && f.active(); ++i) {
    const Wheels w = f.step(p);
    const double v = (w.left + w.right) / 200.0, om = (w.right - w.left) / 100.0 / 0.6;
    p.x += v * std::cos(p.heading) * 0.1;
    p.y += v * std::sin(p.heading) * 0.1;
    p.heading += om * 0.1;
  }
  return p;
}

TEST(PathFollower, TurnsThenDrivesForwardAndBackward) {
  PathFollower f;
  const std::array<Leg, 3> legs = {Leg{{1.0, 1.0}, plan::kPi / 4, true, true, 0},
                                   Leg{{0.5, 0.5}, plan::kPi / 4, false, true, 1},
                                   Leg{{0.5, 0.5}, -plan::kPi / 2, true, false, 2}};
  f.start(legs);
  const plan::Pose2 end = drive(f, {0.0, 0.0, 0.0}, 2000);
  EXPECT_FALSE(f.active());
  EXPECT_NEAR(end.x, 0.5, 0.03);
  EXPECT_NEAR(end.y, 0.5, 0.03);
  EXPECT_NEAR(end.heading, -plan::kPi / 2, 0.04);  // turned clockwise, as the leg asks
  EXPECT_EQ(f.step(end).left, 0);
}

// Why (issue #22: seed 000 wrote one picture per plan): a plan whose picture cannot be handed
// over while the writer still holds the last one is counted, never lost without a word (the
// planner logs each drop; robuterd prints the totals at exit).
TEST(PictureMailbox, ABusySlotDropsThePictureAndCountsIt) {
  planner::PictureMailbox box;
  ASSERT_NE(box.try_fill(), nullptr);
  box.publish();
  EXPECT_EQ(box.try_fill(), nullptr);  // ready, not yet taken: dropped
  ASSERT_NE(box.take(), nullptr);
  EXPECT_EQ(box.try_fill(), nullptr);  // being drawn: dropped
  box.release();
  ASSERT_NE(box.try_fill(), nullptr);  // free again
  box.publish();
  EXPECT_EQ(box.published(), 2u);
  EXPECT_EQ(box.dropped(), 2u);
}

}  // namespace
}  // namespace robuter::planner
