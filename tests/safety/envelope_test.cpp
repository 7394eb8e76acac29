// SPDX-License-Identifier: GPL-3.0-or-later
// Unit tests of the envelope: the evidence grid, the swept body and its cap, the gate's two stops.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include "modules/emergency/evidence_grid.hpp"
#include "modules/emergency/motion_gate.hpp"
#include "modules/emergency/pose_history.hpp"
#include "modules/emergency/swept_envelope.hpp"
#include "tests/support/sample.hpp"

namespace robuter::emergency {
namespace {

using Eigen::Vector2d;

constexpr std::uint64_t kAge = 300;  // free certificates count this long, ticks
constexpr double kPi = 3.14159265358979323846;

// A grid placed around the origin.
EvidenceGrid placed_grid() {
  EvidenceGrid g{GridSettings{}};
  g.follow({0.0, 0.0});
  return g;
}

TEST(EvidenceGrid, AReadingCertifiesItsConeFreeAndMarksItsArc) {
  EvidenceGrid g = placed_grid();
  g.add_reading(10, {0.0, 0.0}, 0.0, 1.01, false, true);
  EXPECT_EQ(g.state({0.10, 0.0}, 10, kAge), CellState::unknown) << "inside the blanking range";
  EXPECT_EQ(g.state({0.25, 0.0}, 10, kAge), CellState::free);
  EXPECT_EQ(g.state({0.90, 0.0}, 10, kAge), CellState::free);
  EXPECT_EQ(g.state({0.97, 0.0}, 10, kAge), CellState::unknown) << "range noise allowance before the echo";
  EXPECT_EQ(g.state({1.01, 0.0}, 10, kAge), CellState::obstacle);
  EXPECT_EQ(g.state({1.01 * std::cos(0.2), 1.01 * std::sin(0.2)}, 10, kAge), CellState::obstacle) << "the whole arc";
  EXPECT_EQ(g.state({0.5, 0.3}, 10, kAge), CellState::unknown) << "outside the cone";
  EXPECT_EQ(g.state({1.5, 0.0}, 10, kAge), CellState::unknown) << "behind the echo";
}

TEST(EvidenceGrid, FreeSpaceAgesObstacleEvidencePersists) {
  EvidenceGrid g = placed_grid();
  g.add_reading(10, {0.0, 0.0}, 0.0, 1.01, false, true);
  EXPECT_EQ(g.state({0.5, 0.0}, 10 + kAge, kAge), CellState::free);
  EXPECT_EQ(g.state({0.5, 0.0}, 11 + kAge, kAge), CellState::stale);
  EXPECT_EQ(g.state({1.01, 0.0}, 100'000, kAge), CellState::obstacle);
}

TEST(EvidenceGrid, ANewerReadingThroughTheArcContradictsIt) {
  EvidenceGrid g = placed_grid();
  g.add_reading(10, {0.0, 0.0}, 0.0, 1.0, false, true);
  g.add_reading(20, {0.0, 0.0}, 0.0, 2.0, false, true);
  EXPECT_EQ(g.state({1.0, 0.0}, 20, kAge), CellState::free);
  EXPECT_EQ(g.state({2.0, 0.0}, 20, kAge), CellState::obstacle);
}

// Multipath (docs/SAFETY.md §13): a wall square to one transducer echoes to it and is marked; a
// transducer that meets the same wall too obliquely to echo may hear, by a bounce off it, a
// surface beyond — a reading longer than the wall. That reading clears no evidence seen along
// another line of sight; a longer echo along nearly the evidence's own line still clears it.
TEST(EvidenceGrid, ALongEchoClearsEvidenceOnlyAlongNearlyTheLineOfSightItWasSeenAlong) {
  EvidenceGrid g = placed_grid();
  const Vector2d wall(1.01, 0.0);
  g.add_reading(10, {0.0, 0.0}, 0.0, 1.01, false, true);
  ASSERT_EQ(g.state(wall, 10, kAge), CellState::obstacle);
  // From 0.8 m aside, 38° off the first line of sight: a 2.4 m reading (the bounce).
  const Vector2d side(0.0, 0.8);
  g.add_reading(20, side, std::atan2(wall.y() - side.y(), wall.x() - side.x()), 2.4, false, true);
  EXPECT_EQ(g.state(wall, 20, kAge), CellState::obstacle) << "seen from 38° aside: it may be the bounce";
  // 5° off the line, the cell at the cone's edge: a cone that met the surface at the evidence's
  // angle plus 5° may have met it too obliquely all across (the cell is what it glanced off).
  const Vector2d near_line = wall - 1.2 * Vector2d(std::cos(0.087), std::sin(0.087));
  g.add_reading(30, near_line, 0.087 + 0.2, 2.4, false, true);
  EXPECT_EQ(g.state(wall, 30, kAge), CellState::obstacle) << "at the cone's edge";
  // The same line of sight, the cell near the cone's axis: the reflector is not there.
  g.add_reading(40, near_line, 0.087, 2.4, false, true);
  EXPECT_EQ(g.state(wall, 40, kAge), CellState::free) << "nearly along its line of sight, well inside the cone";
  // Evidence no echo marked again for longer than sight_age: any farther echo over it clears it.
  EvidenceGrid h = placed_grid();
  h.set_sight_age(100);
  h.add_reading(10, {0.0, 0.0}, 0.0, 1.01, false, true);
  const double aside = std::atan2(wall.y() - side.y(), wall.x() - side.x());
  h.add_reading(110, side, aside, 2.4, false, true);
  EXPECT_EQ(h.state(wall, 110, kAge), CellState::obstacle) << "100 ticks old: still kept";
  h.add_reading(111, side, aside, 2.4, false, true);
  EXPECT_EQ(h.state(wall, 111, kAge), CellState::free) << "101 ticks old: cleared from aside";
}

// The line of sight of carried evidence turns with the frame (AC): the same physical lines clear
// it, or not, as before the new frame.
TEST(EvidenceGrid, CarriedEvidenceKeepsTheLineOfSightItWasSeenAlong) {
  EvidenceGrid g = placed_grid();
  g.add_reading(10, {0.0, 0.0}, 0.0, 1.01, false, true);
  const double turn = kPi / 2.0;  // the new frame: a quarter turn about the robot
  g.carry(Eigen::Rotation2Dd(turn).toRotationMatrix(), {0.0, 0.0}, {0.0, 0.0});
  const Vector2d wall(0.0, 1.01);  // the marked cell, in the new frame
  ASSERT_EQ(g.state(wall, 10, kAge), CellState::obstacle);
  const Vector2d side(-0.8, 0.0);
  g.add_reading(20, side, std::atan2(wall.y() - side.y(), wall.x() - side.x()), 2.4, false, true);
  EXPECT_EQ(g.state(wall, 20, kAge), CellState::obstacle) << "38° off its line of sight";
  const Vector2d near_line = wall - 1.2 * Vector2d(std::cos(turn + 0.087), std::sin(turn + 0.087));
  g.add_reading(30, near_line, turn + 0.087, 2.4, false, true);
  EXPECT_EQ(g.state(wall, 30, kAge), CellState::free) << "5° off its line of sight, turned with the frame";
}

TEST(EvidenceGrid, AReadingThatDoesNotContradictLeavesEvidenceOneThatDoesClearsIt) {
  EvidenceGrid g = placed_grid();
  g.add_reading(10, {0.0, 0.0}, 0.0, 1.01, false, true);
  g.add_reading(20, {0.0, 0.0}, 0.0, 4.95, true, false);  // a lost echo
  EXPECT_EQ(g.state({1.01, 0.0}, 20, kAge), CellState::obstacle);
  EXPECT_EQ(g.state({0.5, 0.0}, 20, kAge), CellState::free);
  EXPECT_EQ(g.state({2.0, 0.0}, 20, kAge), CellState::free) << "free beyond, up to the reach";
  EXPECT_EQ(g.state({2.6, 0.0}, 20, kAge), CellState::unknown) << "past the reach";
  g.add_reading(30, {0.0, 0.0}, 0.0, 4.95, true, true);  // allowed to contradict
  EXPECT_EQ(g.state({1.01, 0.0}, 30, kAge), CellState::free);
}

// The point of an arc of `range` from `origin` at `angle` off the x axis.
Vector2d on_arc(const Vector2d& origin, double range, double angle) {
  return origin + range * Vector2d(std::cos(angle), std::sin(angle));
}

// Known structure for the tests: discs (an a-priori map's walls, as far as an arc can tell).
class Discs final : public KnownStructure {
 public:
  explicit Discs(std::vector<std::pair<Vector2d, double>> discs) : discs_(std::move(discs)) {}
  bool occupied(const Vector2d& p) const override {
    for (const auto& [c, r] : discs_)
      if ((p - c).norm() <= r) return true;
    return false;
  }

 private:
  std::vector<std::pair<Vector2d, double>> discs_;
};

// A grid that narrows arcs (cones up to kAge old), explained by `known`.
EvidenceGrid narrowing_grid(KnownStructure* known, std::uint64_t age = kAge) {
  GridSettings gs;
  gs.narrow_age = age;
  EvidenceGrid g{gs};
  g.set_known_structure(known);
  g.follow({0.0, 0.0});
  return g;
}

// A door's jamb, known from the map: cone A looks through the opening (its echo 2 m away), cone
// B, 0.2 m to its left, meets the jamb at 1 m at its cone's edge. B's arc is explained by the
// jamb; where A saw through along nearly B's line of sight the reflector is not, so the evidence
// goes to the jamb and the rest of the arc only.
const Vector2d kB{0.0, 0.2};                          // B's transducer
const SeenCone kA{10, {0.0, 0.0}, 0.0, 2.0};          // A: through the opening
Discs kJamb({{on_arc(kB, 1.0, 0.2), 0.03}});    // the jamb, at B's cone's edge

// B's reading at `tick` with the grid's cones `seen` (A by default), after A's.
EvidenceGrid after_b(KnownStructure* known, std::uint64_t tick = 12, const SeenCone& a = kA,
                     std::uint64_t age = kAge) {
  EvidenceGrid g = narrowing_grid(known, age);
  g.add_reading(a.tick, a.origin, a.direction, a.range, false, true);
  const std::array<SeenCone, 1> seen{a};
  g.certify_cone(tick, kB, 0.0, 1.0, false, true);
  g.mark_arc(tick, kB, 0.0, 1.0, false, seen);
  return g;
}

TEST(EvidenceGrid, AnArcExplainedByKnownStructureLosesWhatOtherConesSawThrough) {
  const EvidenceGrid g = after_b(&kJamb);
  EXPECT_EQ(g.state(on_arc(kB, 1.0, -0.15), 12, kAge), CellState::free) << "A saw through here";
  EXPECT_EQ(g.state(on_arc(kB, 1.0, 0.2), 12, kAge), CellState::obstacle) << "the jamb";
  EXPECT_EQ(g.state(on_arc(kB, 1.0, 0.18), 12, kAge), CellState::obstacle) << "beyond A's cone";
  EXPECT_GT(g.narrowed_cells(), 0u);
  EXPECT_EQ(g.unexplained_echoes(), 1u) << "A's own echo (the far room): no structure on its arc";
  const EvidenceGrid off = after_b(&kJamb, 12, kA, 0);  // narrow_age 0 ([emergency] narrow_arcs = false)
  EXPECT_EQ(off.state(on_arc(kB, 1.0, -0.15), 12, kAge), CellState::obstacle) << "narrowing off: the whole arc";
  EXPECT_EQ(off.narrowed_cells(), 0u);
}

// Unexplained, an echo keeps its whole arc, whatever the cones saw: a face may echo to one
// transducer and be too oblique for its neighbour (seeds 6604 and 9853 of the random sequences
// touched a box when cones alone narrowed arcs), and something may have stepped in since.
TEST(EvidenceGrid, AnArcNoKnownStructureExplainsIsMarkedWhole) {
  Discs elsewhere({{{5.0, 5.0}, 0.5}});
  for (KnownStructure* known : {static_cast<KnownStructure*>(nullptr),
                                      static_cast<KnownStructure*>(&elsewhere)}) {
    const EvidenceGrid g = after_b(known);
    EXPECT_EQ(g.state(on_arc(kB, 1.0, -0.15), 12, kAge), CellState::obstacle);
    EXPECT_EQ(g.narrowed_cells(), 0u);
  }
  EXPECT_EQ(after_b(&elsewhere).unexplained_echoes(), 2u) << "A's and B's";
}

// What a cone may rule out: only while it is at most the age old, and only along nearly the
// echo's line of sight (within 20°; a cone that looked through the point from a side says nothing
// of a face turned to the echo's transducer).
TEST(EvidenceGrid, OnlyARecentConeAlongNearlyTheSameLineOfSightRulesAPointOut) {
  const Vector2d p = on_arc(kB, 1.0, -0.15);
  EXPECT_EQ(after_b(&kJamb, 10 + kAge).state(p, 10 + kAge, kAge), CellState::free) << "exactly the age";
  EXPECT_EQ(after_b(&kJamb, 11 + kAge).state(p, 11 + kAge, kAge), CellState::obstacle) << "older than the age";
  // The same point seen through from 1 m to the side, 40° off B's line of sight.
  const double sight = -0.15 - 0.7;
  const Vector2d side = p - Vector2d(std::cos(sight), std::sin(sight));
  const SeenCone across{10, side, sight, 2.0};
  const EvidenceGrid probe = narrowing_grid(&kJamb);
  ASSERT_TRUE(probe.sees_through(across, p, side, 12)) << "the cone does contain p";
  EXPECT_FALSE(probe.sees_through(across, p, kB, 12)) << "but not along B's line of sight";
  EXPECT_EQ(after_b(&kJamb, 12, across).state(p, 12, kAge), CellState::obstacle);
}

// A wall's echo at the edge of a cone, 2 m away, across the window's edge: the wall is outside
// the window, the rest of the arc inside. The wall explains the echo all the same (before
// 2026-12-05 only samples inside the window were tested: the echo was unexplained and its arc
// hard evidence for good — a robot in a corridor of the building floor stopped 0.7 m short of
// such an arc, with nothing there).
TEST(EvidenceGrid, AWallOutsideTheWindowExplainsAnEcho) {
  const Vector2d o(3.0, 0.0);                      // the window holds x < 3.2 m
  const double wall_at = kPi / 2 - 0.218166;       // the cone's right edge
  Discs wall({{on_arc(o, 2.0, wall_at), 0.03}});
  EvidenceGrid g = narrowing_grid(&wall);
  g.add_reading(10, o, kPi / 2, 2.0, false, true);
  EXPECT_EQ(g.unexplained_echoes(), 0u);
  const Vector2d inside = on_arc(o, 2.0, kPi / 2 + 0.15);
  EXPECT_EQ(g.state(inside, 10, kAge), CellState::obstacle) << "nothing ruled it out";
  g.add_reading(20, o, kPi / 2, 4.95, true, false);  // no echo along the same line
  EXPECT_EQ(g.state(inside, 20, kAge), CellState::free);
}

// What is left of an explained arc off the structure is soft evidence: a later no-echo looking
// along nearly the same line of sight clears it (the structure, not something in the open,
// explains the echo, and now nothing answers from there); the structure's own cells, an
// unexplained arc, and a no-echo from the side (a face turned to the echo's transducer may be
// too oblique for it) leave their evidence.
TEST(EvidenceGrid, ANoEchoAlongTheSameLineClearsOnlySoftEvidence) {
  const Vector2d o(0.0, 0.0);
  Discs corner({{on_arc(o, 1.5, 0.2), 0.03}});  // a wall corner at the cone's edge
  const Vector2d open = on_arc(o, 1.5, -0.1);         // the arc, in the open
  const Vector2d wall = on_arc(o, 1.5, 0.2);
  for (KnownStructure* known : {static_cast<KnownStructure*>(&corner),
                                      static_cast<KnownStructure*>(nullptr)}) {
    EvidenceGrid g = narrowing_grid(known);
    g.add_reading(10, o, 0.0, 1.5, false, true);
    ASSERT_EQ(g.state(open, 10, kAge), CellState::obstacle);
    // From the side: 1.2 m away, 59° off the line of sight.
    const Vector2d side = open + Vector2d(0.0, 1.0) - 0.5 * Vector2d(std::cos(-0.1), std::sin(-0.1));
    const Vector2d to_open = open - side;
    g.add_reading(20, side, std::atan2(to_open.y(), to_open.x()), 4.95, true, false);
    EXPECT_EQ(g.state(open, 20, kAge), CellState::obstacle) << "a no-echo from the side";
    // Along the line of sight, from 0.3 m nearer.
    const Vector2d nearer = 0.3 * Vector2d(std::cos(-0.1), std::sin(-0.1));
    g.add_reading(30, nearer, -0.1, 4.95, true, false);
    if (known != nullptr) {
      EXPECT_EQ(g.state(open, 30, kAge), CellState::free) << "soft evidence, looked at again";
      g.add_reading(40, o, 0.2, 4.95, true, false);  // no echo, looking straight at the corner
      EXPECT_EQ(g.state(wall, 40, kAge), CellState::obstacle) << "the structure's own cell is hard";
    } else {
      EXPECT_EQ(g.state(open, 30, kAge), CellState::obstacle) << "an unexplained echo is hard";
    }
  }
}

// One echo that no later echo marks again counts single_age ticks (a spurious echo's arc, left
// where no cone of the ring looks again: docs/SAFETY.md §13, "Unconfirmed"); then the cell is
// what its certificates say. A second echo on the cell confirms it for good.
TEST(EvidenceGrid, OneEchoNotMarkedAgainCountsSingleAgeASecondConfirmsIt) {
  EvidenceGrid g = placed_grid();
  g.set_single_age(300);
  g.add_reading(10, {0.0, 0.0}, 0.0, 1.01, false, true);
  ASSERT_EQ(g.state({1.01, 0.0}, 10, kAge), CellState::obstacle);
  EXPECT_EQ(g.state({1.01, 0.0}, 310, kAge), CellState::obstacle) << "within single_age";
  EXPECT_EQ(g.state({1.01, 0.0}, 311, kAge), CellState::unknown) << "past it: never certified, unknown";
  // A second echo from elsewhere whose arc crosses the cell: confirmed, for good.
  g.add_reading(20, {0.0, 0.5}, -std::atan2(0.5, 1.01), std::hypot(1.01, 0.5), false, true);
  EXPECT_EQ(g.state({1.01, 0.0}, 100'000, kAge), CellState::obstacle) << "two echoes: confirmed";
  // Without single_age (the default) one echo counts for ever.
  EvidenceGrid h = placed_grid();
  h.add_reading(10, {0.0, 0.0}, 0.0, 1.01, false, true);
  EXPECT_EQ(h.state({1.01, 0.0}, 100'000, kAge), CellState::obstacle);
}

// AC sets the odometry: the robot stays, its coordinates move. Evidence goes with the world into
// the new frame (never narrower), free certificates are forgotten.
TEST(EvidenceGrid, ANewOdometryFrameCarriesTheEvidenceAndForgetsFreeSpace) {
  EvidenceGrid g = placed_grid();
  g.add_reading(10, {0.0, 0.0}, 0.0, 1.01, false, true);  // evidence at (1.01, 0), free before it
  ASSERT_EQ(g.state({1.01, 0.0}, 10, kAge), CellState::obstacle);
  // The new frame: the robot at the origin facing +x becomes (5, -3) facing +y.
  const Eigen::Matrix2d rot = Eigen::Rotation2Dd(M_PI / 2).toRotationMatrix();
  const Vector2d trans(5.0, -3.0);
  g.carry(rot, trans, trans);
  EXPECT_EQ(g.state({5.0, -3.0 + 1.01}, 10, kAge), CellState::obstacle) << "the box, where it is in the new frame";
  EXPECT_EQ(g.state({5.0 + 1.01 * std::sin(0.2), -3.0 + 1.01 * std::cos(0.2)}, 10, kAge), CellState::obstacle)
      << "the whole arc";
  EXPECT_EQ(g.state({5.0, -3.0 + 0.5}, 10, kAge), CellState::unknown) << "free space is certified again";
  EXPECT_EQ(g.state({1.01, 0.0}, 10, kAge), CellState::unknown) << "nothing left at the old coordinates";
  // A turn that is not a quarter turn and a translation off the cells: every point that was
  // evidence still is, at its new coordinates (sampled at a fifth of a cell).
  EvidenceGrid before = placed_grid();
  before.add_reading(10, {0.0, 0.0}, 0.0, 0.60, false, true);
  EvidenceGrid after = before;
  const Eigen::Matrix2d r30 = Eigen::Rotation2Dd(0.5236).toRotationMatrix();
  const Vector2d t(0.013, -0.007);
  after.carry(r30, t, t);
  int evidence = 0;
  for (double x = 0.4; x <= 0.7; x += 0.005) {
    for (double y = -0.2; y <= 0.2; y += 0.005) {
      if (before.state({x, y}, 10, kAge) != CellState::obstacle) continue;
      ++evidence;
      EXPECT_EQ(after.state(r30 * Vector2d(x, y) + t, 10, kAge), CellState::obstacle) << x << ", " << y;
    }
  }
  EXPECT_GT(evidence, 100);
}

// An operator who sets the odometry again and again at rest (AC, turned one way then back)
// must not grow the evidence: each carry may widen it by the turned cells' boxes, but the
// evidence is where the obstacle is, so repeated frames may not close in on the robot.
TEST(EvidenceGrid, ManyOdometrySetsAtRestDoNotGrowTheEvidence) {
  EvidenceGrid g = placed_grid();
  g.add_reading(10, {0.0, 0.0}, 0.0, 0.60, false, true);  // a face 0.60 m ahead
  const Eigen::Matrix2d there = Eigen::Rotation2Dd(0.5236).toRotationMatrix();
  const Eigen::Matrix2d back = there.transpose();
  const Vector2d t(0.013, -0.007);
  for (int i = 0; i < 40; ++i) {  // 40 frames: 20 times turned 30 degrees and back, shifted and back
    g.carry(there, t, t);
    g.carry(back, -(back * t), {0.0, 0.0});
  }
  EXPECT_EQ(g.state({0.60, 0.0}, 10, kAge), CellState::obstacle) << "the face is still there";
  int grown = 0;
  for (double x = -1.0; x <= 1.0; x += 0.01) {
    for (double y = -1.0; y <= 1.0; y += 0.01) {
      const double d = std::hypot(x, y);
      if (g.state({x, y}, 10, kAge) == CellState::obstacle && (d < 0.50 || d > 0.70)) ++grown;
    }
  }
  EXPECT_EQ(grown, 0) << "evidence more than 0.10 m from the face after 80 frames";
}

TEST(EvidenceGrid, TheBodyIsFreeAndTheWindowForgetsWhatItLeaves) {
  EvidenceGrid g = placed_grid();
  g.add_reading(10, {-0.5, 0.0}, 0.0, 0.5, false, true);  // evidence at x = 0
  g.certify_rectangle(11, {0.0, 0.0}, 0.0, {-0.33, -0.35}, {0.695, 0.35});
  EXPECT_EQ(g.state({0.0, 0.0}, 11, kAge), CellState::free) << "under the body";
  EXPECT_EQ(g.state({0.72, 0.0}, 11, kAge), CellState::unknown) << "the face's own cell is not wholly under it";
  g.add_reading(12, {0.0, 0.0}, 0.0, 1.0, false, true);
  g.follow({5.0, 0.0});  // the window moves 5 m: the old cells are gone
  EXPECT_EQ(g.state({1.0, 0.0}, 12, kAge), CellState::unknown);
  g.reset();
  EXPECT_EQ(g.state({1.0, 0.0}, 12, kAge), CellState::unknown);
}

// One fold of a heading for every module (robot/angles.hpp): exact, and bounded work for any
// input — the history's own loop, which subtracted 2π until the angle was in range, never ended
// on a heading of 1e18 rad (2π is below its rounding step there).
TEST(PoseHistory, AHugeHeadingIsFoldedInBoundedWork) {
  const Pose2 out = advance(Pose2{Eigen::Vector2d::Zero(), 1e18}, 0.0, 0.0, 1.0);
  EXPECT_GT(out.theta, -std::numbers::pi);
  EXPECT_LE(out.theta, std::numbers::pi);
  EXPECT_DOUBLE_EQ(advance(Pose2{Eigen::Vector2d::Zero(), 3.5 * std::numbers::pi}, 0.0, 0.0, 1.0).theta,
                   -0.5 * std::numbers::pi);
}

TEST(PoseHistory, InterpolatesExtrapolatesAndDetectsASetOdometry) {
  PoseHistory h;
  EXPECT_TRUE(h.add(0, {{0.0, 0.0}, 0.0}, 0.03, 0.08));
  EXPECT_TRUE(h.add(10, {{0.1, 0.0}, 0.0}, 0.03, 0.08));
  EXPECT_NEAR(h.at(5).p.x(), 0.05, 1e-12);
  EXPECT_NEAR(h.at(15).p.x(), 0.15, 1e-12) << "along the last velocity";
  EXPECT_NEAR(h.velocity().v, 0.01, 1e-12);
  EXPECT_FALSE(h.add(20, {{3.0, 1.0}, 1.0}, 0.03, 0.08)) << "AC: a jump no robot makes";
  EXPECT_NEAR(h.at(25).p.x(), 3.0, 1e-12);
}

// A robot at the origin facing +x whose surroundings were all seen free recently.
struct Scene {
  EnvelopeSettings s;
  EvidenceGrid g = placed_grid();
  Pose2 now;
  std::uint64_t tick = 100;
  // Everything within 3 m certified free at `tick` (a world already looked at).
  void all_free() {
    for (int k = 0; k < 72; ++k) g.add_reading(tick, {0.0, 0.0}, k * 5.0 * 3.14159265358979 / 180.0, 4.95, true, true);
    for (int k = 0; k < 72; ++k) g.add_reading(tick, {0.3, 0.0}, k * 5.0 * 3.14159265358979 / 180.0, 4.95, true, true);
    for (int k = 0; k < 72; ++k) g.add_reading(tick, {-0.3, 0.0}, k * 5.0 * 3.14159265358979 / 180.0, 4.95, true, true);
    for (double x : {0.695, 0.3, -0.33})
      for (double y : {-0.35, 0.0, 0.35})
        for (int k = 0; k < 72; ++k) g.add_reading(tick, {x, y}, k * 5.0 * 3.14159265358979 / 180.0, 4.95, true, true);
    g.certify_rectangle(tick, now.p, now.theta, {-s.rear, -s.half_width}, {s.front, s.half_width});
  }
};

TEST(SweptEnvelope, OpenSpaceGrantsAllAndTheHorizonInvertsExactly) {
  Scene sc;
  sc.all_free();
  SweptEnvelope env(sc.s);
  const EnvelopeVerdict v = env.judge(sc.g, sc.now, 1.0, 1.0, sc.tick, nullptr);
  EXPECT_DOUBLE_EQ(v.fraction, 1.0);
  EXPECT_FALSE(v.obstacle);
  for (double k : {0.1, 0.5, 0.9}) EXPECT_NEAR(env.fraction_for(env.horizon(k, 0.6, 1.0), 0.6, 1.0), k, 1e-12);
}

// The straight approach of docs/SAFETY.md §13: obstacle evidence d ahead of the front face, the
// granted speed at least 90 % of v with v·t_r + v²/2a = d − margin − quantum.
TEST(SweptEnvelope, AStraightApproachGetsAtLeastNinetyPercentOfTheAnalyticCap) {
  for (double d : {0.15, 0.25, 0.4, 0.6, 0.9}) {
    Scene sc;
    sc.all_free();
    // A wall across the path d ahead of the front face, seen by a sensor on the face.
    for (double y = -0.6; y <= 0.6; y += 0.05) sc.g.add_reading(sc.tick, {0.695 - 1.2, y}, 0.0, 1.2 + d, false, true);
    SweptEnvelope env(sc.s);
    const EnvelopeVerdict v = env.judge(sc.g, sc.now, 1.0, 1.0, sc.tick, nullptr);
    const double free = d - sc.s.margin - 0.05;
    const double cap = free <= 0 ? 0.0 : sc.s.decel * (-sc.s.reaction + std::sqrt(sc.s.reaction * sc.s.reaction + 2 * free / sc.s.decel));
    SCOPED_TRACE(testing::Message() << "d " << d << " m: granted " << v.fraction << " m/s, cap " << cap);
    EXPECT_GE(v.fraction + 1e-9, 0.9 * std::min(1.0, cap));
    // and never more than what stops within d − margin (the sample gap allowed)
    EXPECT_LE(env.horizon(v.fraction, 1.0, sc.s.decel) * 1.0, d - sc.s.margin + sc.s.step);
  }
}

TEST(SweptEnvelope, BackingAwayFromAWallAheadIsFreeDrivingIntoItIsAProtectiveStop) {
  Scene sc;
  sc.all_free();
  for (double y = -0.6; y <= 0.6; y += 0.05) sc.g.add_reading(sc.tick, {0.0, y}, 0.0, 0.72, false, true);  // 25 mm ahead
  SweptEnvelope env(sc.s);
  const EnvelopeVerdict fwd = env.judge(sc.g, sc.now, 0.3, 0.3, sc.tick, nullptr);
  EXPECT_EQ(fwd.fraction, 0.0);
  EXPECT_TRUE(fwd.obstacle);
  const EnvelopeVerdict back = env.judge(sc.g, sc.now, -0.3, -0.3, sc.tick, nullptr);
  EXPECT_DOUBLE_EQ(back.fraction, 1.0);
  EXPECT_FALSE(env.judge(sc.g, sc.now, -0.3, 0.3, sc.tick, nullptr).fraction > 0.5) << "turning in place swings a front corner into it";
}

// A start pose: the robot stood at `at` while the ring made its full passes, every sensor read.
StartBlind rested(const Pose2& at) {
  StartBlind b{StartBlindSettings{}};
  std::array<std::uint64_t, 24> read{};
  b.observe(10, at, true, 0, read.data(), 24);
  read.fill(20);
  b.observe(30, at, true, 2, read.data(), 24);
  return b;
}

TEST(SweptEnvelope, UnknownNearFieldAllowsACreepUnknownFarFieldNothing) {
  Scene sc;  // nothing seen at all
  SweptEnvelope env(sc.s);
  sc.g.certify_rectangle(sc.tick, sc.now.p, sc.now.theta, {-sc.s.rear, -sc.s.half_width}, {sc.s.front, sc.s.half_width});
  const StartBlind start = rested(sc.now);
  ASSERT_TRUE(start.valid());
  const EnvelopeVerdict v = env.judge(sc.g, sc.now, 0.3, 0.3, sc.tick, &start);
  EXPECT_NEAR(v.fraction * 0.3, sc.s.creep, 1e-9) << "a creep through the blind near field";
  EXPECT_TRUE(v.missing);
  EXPECT_FALSE(v.obstacle);
  // Without the bumpers, nothing senses there: a hold, not a creep.
  const EnvelopeVerdict masked = env.judge(sc.g, sc.now, 0.3, 0.3, sc.tick, &start, true, false);
  EXPECT_EQ(masked.fraction, 0.0);
  EXPECT_TRUE(masked.missing);
  EXPECT_FALSE(masked.obstacle);
  // Obstacle evidence inside the near field: not even a creep.
  sc.g.add_reading(sc.tick, {0.0, 0.0}, 0.0, 0.71, false, true);
  const EnvelopeVerdict w = env.judge(sc.g, sc.now, 0.3, 0.3, sc.tick, &start);
  EXPECT_EQ(w.fraction, 0.0);
  EXPECT_TRUE(w.obstacle);
}

// The UD1000 wall of the whole-firmware matrix, as a unit: a robot that moved into space its ring
// could have seen but did not read (no start pose here: it came there moving) is held, not let
// creep — when any unknown near field allowed a creep, it crept into an unseen wall 19 mm ahead.
TEST(SweptEnvelope, UnseenSpaceReachedByMovingIsAHoldNotACreep) {
  Scene sc;
  SweptEnvelope env(sc.s);
  sc.g.certify_rectangle(sc.tick, sc.now.p, sc.now.theta, {-sc.s.rear, -sc.s.half_width}, {sc.s.front, sc.s.half_width});
  const EnvelopeVerdict v = env.judge(sc.g, sc.now, 0.3, 0.3, sc.tick, nullptr);
  EXPECT_EQ(v.fraction, 0.0);
  EXPECT_TRUE(v.missing);
  EXPECT_FALSE(v.obstacle);
  // A start pose 0.5 m back: the space now ahead of the face was in its front cones, not blind.
  const StartBlind back = rested({{-0.5, 0.0}, 0.0});
  EXPECT_FALSE(back.covers({0.75, 0.0})) << "in front of the face, seen from 0.5 m back";
  EXPECT_EQ(env.judge(sc.g, sc.now, 0.3, 0.3, sc.tick, &back).fraction, 0.0);
  // From here, at rest: blind (inside the blanking range), so a creep.
  EXPECT_TRUE(rested(sc.now).covers({0.75, 0.0}));
}

// Which space is blind from a start pose: the near field, the gaps between the cones that read,
// nothing in a cone that read, nothing beyond the gaps' reach; no start pose, nothing.
TEST(StartBlind, NearFieldAndGapsBetweenTheConesThatRead) {
  StartBlind none{StartBlindSettings{}};
  EXPECT_FALSE(none.covers({0.75, 0.0}));
  const StartBlind b = rested({});
  EXPECT_TRUE(b.covers({0.80, 0.0}));   // 0.105 m ahead of the face: inside the blanking range
  EXPECT_FALSE(b.covers({1.40, 0.0}));  // 0.7 m ahead on the axis: the front sensors' cones
  EXPECT_FALSE(b.covers({3.0, 0.0}));   // beyond the gaps' reach
  StartBlind moved = rested({});
  std::array<std::uint64_t, 24> read{};
  moved.observe(40, {{0.1, 0.0}, 0.0}, false, 2, read.data(), 24);  // moving: the start stays
  EXPECT_TRUE(moved.valid());
  StartBlind far = rested({});
  far.observe(40, {{0.7, 0.0}, 0.0}, false, 2, read.data(), 24);  // … for the start's first 0.65 m
  EXPECT_FALSE(far.valid());
  moved.observe(50, {{0.2, 0.0}, 0.0}, true, 2, read.data(), 24);   // at rest again: a new one later
  EXPECT_FALSE(moved.valid());
}

// A judge that answers what the test says.
struct FakeJudge final : EnvelopeJudge {
  EnvelopeVerdict verdict;
  EnvelopeVerdict judge(std::int32_t, std::int32_t, bool) override { return verdict; }
};

struct EnvelopeGate {
  MotionGate gate{MotionGateSettings{}};
  FakeJudge judge;
  std::uint64_t tick = 1000;
  GateDecision step(GateInputs in = {}) {
    ++tick;
    in.tick = tick;
    in.last_message_tick = tick;
    in.envelope = &judge;
    return gate.step(in);
  }
  GateDecision request(int l, int r, bool automatic) {
    GateInputs in;
    in.new_request = true;
    in.left = l;
    in.right = r;
    in.automatic = automatic;
    in.source = automatic ? MotionSource::planner : MotionSource::link;
    return step(in);
  }
};

TEST(EnvelopeGate, GrantsTheEnvelopesShareOfTheRequest) {
  EnvelopeGate g;
  g.judge.verdict.fraction = 0.5;
  const GateDecision d = g.request(40, 30, false);
  EXPECT_EQ(d.left, 20);
  EXPECT_EQ(d.right, 15);
  EXPECT_EQ(d.state.granted_pct, 50);
  EXPECT_TRUE(d.state.envelope);
  EXPECT_EQ(scaled(-33, 0.5), -16) << "towards zero";
}

TEST(EnvelopeGate, AProtectiveStopForgetsAnOperatorsMotionWithoutALatch) {
  EnvelopeGate g;
  g.judge.verdict = {0.0, true, false, 0};
  const GateDecision d = g.request(30, 30, false);
  EXPECT_EQ(d.left, 0);
  EXPECT_FALSE(d.stop) << "servo kept: not an emergency";
  EXPECT_TRUE(d.state.protective);
  EXPECT_FALSE(d.state.latched);
  EXPECT_EQ(d.state.cause, EmergencyCause::none);
  EXPECT_EQ(d.state.trips, 0u);
  EXPECT_EQ(d.state.protective_stops, 1u);
  g.judge.verdict = {1.0, false, false, 0};
  EXPECT_EQ(g.step().left, 0) << "forgotten: clear space does not restart it";
  EXPECT_EQ(g.request(-20, -20, false).left, -20) << "a new request is judged at once";
  EXPECT_FALSE(g.step().state.protective);
}

TEST(EnvelopeGate, AnAutomaticRequestResumesAfterItsEnvelopeWasClearForTheClearTime) {
  EnvelopeGate g;
  g.judge.verdict = {0.0, true, false, 0};
  EXPECT_TRUE(g.request(30, 30, true).state.protective);
  g.judge.verdict = {1.0, false, false, 0};
  const std::uint64_t clear_from = g.tick + 1;
  GateDecision d = g.step();
  while (d.left == 0 && g.tick < clear_from + 1000) {
    if (g.tick == clear_from + 50) {
      g.judge.verdict = {0.0, true, false, 0};  // evidence again: the clock starts over
      d = g.step();
      EXPECT_EQ(d.state.protective_stops, 1u) << "one pause, not a new stop";
      g.judge.verdict = {1.0, false, false, 0};
    }
    d = g.step();
  }
  EXPECT_EQ(d.left, 30);
  EXPECT_TRUE(d.resumed);
  EXPECT_GE(g.tick - clear_from, 150u) << "50 ticks, then the whole clear time again";
  EXPECT_FALSE(d.state.protective);
}

TEST(EnvelopeGate, MissingDataHoldsLikeTheSeed) {
  EnvelopeGate g;
  g.judge.verdict = {0.0, false, true, 0};
  const GateDecision d = g.request(30, 30, false);
  EXPECT_TRUE(d.state.held);
  EXPECT_FALSE(d.state.protective);
  g.judge.verdict = {1.0, false, false, 0};
  EXPECT_EQ(g.step().left, 30) << "resumes by itself when the data comes";
}

}  // namespace
}  // namespace robuter::emergency
