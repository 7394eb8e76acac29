// SPDX-License-Identifier: GPL-3.0-or-later
// The kept tree: replans after new obstacles and robot moves cost what a plain search finds.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "modules/planner/lib/heading_search.hpp"
#include "modules/planner/lib/planner.hpp"
#include "tests/planner/test_util.hpp"
#include "tests/support/sample.hpp"

namespace robuter::plan {
namespace {

// Why: a rectangle of 35 x 25 cm, 5 cm ahead of its axle, 8 slices over a half turn (16 over
// the full turn): small enough for maps of a few metres.
PlannerConfig rectangle(double turn_clearance, double unknown_cost = 1.0) {
  PlannerConfig cfg;
  cfg.footprint = FootprintKind::Rectangle;
  cfg.rectangle = RectangleFootprint{0.35, 0.25, 0.05, 0.0};
  cfg.heading_slices = 8;
  cfg.turn_clearance = turn_clearance;
  cfg.unknown_cost = unknown_cost;
  return cfg;
}

// Why: the search's options as the planner derives them.
HeadingOptions options_of(const Planner& p) {
  HeadingOptions opt;
  opt.motion = p.config().motion;
  opt.rotation_step_cost = p.config().rotation_cost * (2.0 * kPi / p.full_turn_slices()) / p.map().resolution();
  return opt;
}

// Why: the reference: one plain search from the robot on the planner's own layers (no tree).
PlanResult plain(const Planner& p, const Pose2& start, Point2 goal) {
  std::vector<const PassGrid*> slices;
  for (int k = 0; k < p.slices(); ++k) slices.push_back(&p.expanded(k));
  const Cell s = p.map().cell_of({start.x, start.y});
  const CellPose sp{s.x, s.y, slice_of_heading(start.heading, p.full_turn_slices())};
  const SliceBits* turns = p.turn_room().slices == p.slices() ? &p.turn_room() : nullptr;
  HeadingSearch search;
  CostModel costs;
  costs.unknown_cost = p.config().unknown_cost;
  return search.find(slices, sp, p.map().cell_of(goal), options_of(p), costs, nullptr, turns);
}

// Why: the waypoints must be a walk of the graph from the robot's pose (turns in the body's own
// room only before the first move) whose edges sum to the plan's cost; -1 if a step is no edge.
double walked(const Planner& p, const Pose2& start) {
  const std::vector<Waypoint>& w = p.waypoints();
  const int k = p.slices();
  const Cell s = p.map().cell_of({start.x, start.y});
  if (w.empty() || w.front().cell.x != s.x || w.front().cell.y != s.y ||
      w.front().cell.slice != slice_of_heading(start.heading, p.full_turn_slices()))
    return -1.0;
  CostModel costs;
  costs.unknown_cost = p.config().unknown_cost;
  const auto table = costs.table();
  const double turn = options_of(p).rotation_step_cost;
  bool moved = false;
  double total = 0.0;
  for (std::size_t i = 1; i < w.size(); ++i) {
    const CellPose a = w[i - 1].cell, b = w[i].cell;
    const Cell c{a.x, a.y};
    if (a.x == b.x && a.y == b.y) {
      const int d = (b.slice - a.slice + k) % k;
      if (d != 1 && d != k - 1) return -1.0;
      const bool room = moved ? p.can_turn(c, a.slice) && p.can_turn(c, b.slice)
                              : p.expanded(a.slice).at(c) != kBlocked;
      if (!room || p.expanded(b.slice).at(c) == kBlocked) return -1.0;
      total += turn;
      continue;
    }
    if (a.slice != b.slice) return -1.0;
    moved = true;
    int m = -1;
    for (int j = 0; j < 8; ++j)
      if (b.x - a.x == kMoveDx[j] && b.y - a.y == kMoveDy[j]) m = j;
    if (m < 0 || !(allowed_moves(a.slice, k, p.config().motion) & (1u << m))) return -1.0;
    const PassGrid& g = p.expanded(a.slice);
    const std::uint8_t ca = g.at(c), cb = g.at({b.x, b.y});
    if (ca == kBlocked || cb == kBlocked) return -1.0;
    if (m >= 4 && (g.at({a.x + kMoveDx[m], a.y}) == kBlocked || g.at({a.x, a.y + kMoveDy[m]}) == kBlocked))
      return -1.0;
    total += table[m][ca][cb];
  }
  const Cell end{w.back().cell.x, w.back().cell.y};
  return end == p.map().cell_of({w.back().pose.x, w.back().pose.y}) ? total : -1.0;
}

// Why: a map of free cells with random boxes (some unknown patches when `unknown`).
OccupancyMap random_map(std::mt19937& rng, int w, int h, int boxes, bool unknown) {
  OccupancyMap map = test::free_map(w, h);
  for (int b = 0; b < boxes; ++b) {
    const int x0 = static_cast<int>(rng() % static_cast<unsigned>(w)), y0 = static_cast<int>(rng() % static_cast<unsigned>(h));
    const int sx = 2 + static_cast<int>(rng() % 7), sy = 2 + static_cast<int>(rng() % 7);
    for (int y = y0; y < y0 + sy && y < h; ++y)
      for (int x = x0; x < x0 + sx && x < w; ++x) map.mark_occupied({x, y});
  }
  if (unknown) {
    OccupancyMap fresh(map.geometry());  // all unknown
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const bool patch = ((x / 10) + (y / 10)) % 3 == 0;
        if (!patch && map.state({x, y}) == CellState::Free) fresh.mark_free({x, y});
        if (map.state({x, y}) == CellState::Occupied) fresh.mark_occupied({x, y});
      }
    map = fresh;
  }
  map.clear_changes();
  return map;
}

// Why: the robot at waypoint i of the last plan (its cell centre and slice heading).
Pose2 along(const Planner& p, std::size_t i) {
  const std::vector<Waypoint>& w = p.waypoints();
  return w[std::min(i, w.size() - 1)].pose;
}

// Every replan of the kept tree — blocks raised on the path ahead and elsewhere, earlier blocks
// cleared, the robot moving along its plan and jumping off it, turn clearance or not, unknown
// cells dearer or not — costs what a plain search from the robot finds, and its waypoints walk
// the graph at that cost.
TEST(KeptTree, ReplansAfterNewObstaclesAndMovesEqualAPlainSearch) {
  std::mt19937 rng(20261204);
  const int maps = ::robuter::test::sample(24, 6);
  int compared = 0, found = 0, kept_replans = 0, clears = 0;
  for (int mi = 0; mi < maps; ++mi) {
    std::vector<Cell> raised;  // corners of the blocks raised on this map
    const PlannerConfig cfg = mi % 3 == 0 ? rectangle(0.05) : mi % 3 == 1 ? rectangle(0.0) : rectangle(0.05, 2.0);
    Planner p(cfg);
    p.set_map(random_map(rng, 90, 70, 14, cfg.unknown_cost > 1.0));
    Pose2 robot{0.3 + 0.05 * static_cast<double>(rng() % 60), 0.3 + 0.05 * static_cast<double>(rng() % 60),
                0.4 * static_cast<double>(rng() % 16)};
    const Point2 goal{0.3 + 0.05 * static_cast<double>(rng() % 80), 0.3 + 0.05 * static_cast<double>(rng() % 60)};
    for (int round = 0; round < 12; ++round) {
      SCOPED_TRACE(testing::Message() << "map " << mi << " round " << round);
      const bool kept = p.tree_kept();
      const PlanResult a = p.plan(robot, goal);
      const PlanResult b = plain(p, robot, goal);
      ASSERT_EQ(a.status, b.status);
      ++compared;
      if (a.found()) {
        ++found;
        kept_replans += kept;
        ASSERT_NEAR(a.cost, b.cost, 1e-9);
        ASSERT_NEAR(walked(p, robot), a.cost, 1e-6);
      }
      // The tree grows while the robot drives (half the time with new obstacles folded in
      // while it grows: it stays sound).
      if (rng() % 2 == 0) p.grow_tree();
      // New obstacles: a block on the path a little ahead (the case the tree is for), or anywhere.
      Cell c{static_cast<int>(rng() % 90), static_cast<int>(rng() % 70)};
      if (a.found() && rng() % 3 != 0) {
        const Waypoint& w = p.waypoints()[std::min<std::size_t>(4 + rng() % 20, p.waypoints().size() - 1)];
        c = {w.cell.x, w.cell.y};
      }
      const int side = 1 + static_cast<int>(rng() % 4);
      const bool clear = !raised.empty() && rng() % 4 == 0;  // an earlier block goes: cheaper, the tree is dropped
      if (clear) {
        const std::size_t i = rng() % raised.size();
        c = raised[i];
        raised.erase(raised.begin() + static_cast<std::ptrdiff_t>(i));
        ++clears;
      } else {
        raised.push_back(c);
      }
      for (int dy = 0; dy < 4; ++dy)
        for (int dx = 0; dx < 4; ++dx) {
          const Cell d{c.x + dx, c.y + dy};
          if (!p.map().contains(d) || (!clear && (dx >= side || dy >= side))) continue;
          if (clear) p.map().mark_free(d);
          else p.map().mark_occupied(d);
        }
      p.sync();
      p.grow_tree();
      // The robot follows its plan a few waypoints, stays, or is somewhere else.
      const unsigned move = rng() % 4;
      if (move == 0 || !a.found())
        robot = Pose2{0.3 + 0.05 * static_cast<double>(rng() % 60), 0.3 + 0.05 * static_cast<double>(rng() % 60),
                      0.4 * static_cast<double>(rng() % 16)};
      else if (move != 1)
        robot = along(p, rng() % 8);
    }
  }
  EXPECT_GT(found, compared / 3);
  EXPECT_GT(kept_replans, compared / 5);
  EXPECT_GT(clears, maps);
}

// Why: the mechanism is in use: after the first plan, a block far from the path changes nothing
// (the robot's own state is still on an intact tree path: no search), and a block on the path
// ahead costs a small part of a fresh plan's search.
TEST(KeptTree, AReplanSearchesOnlyWhereTheTreeBroke) {
  const PlannerConfig cfg = rectangle(0.05);
  OccupancyMap base = test::free_map(160, 60);
  for (int y = 0; y < 40; ++y) base.mark_occupied({80, y});  // a wall to go round
  base.clear_changes();
  Planner p(cfg);
  p.set_map(base);
  const Pose2 robot{0.5, 0.5, 0.0};
  const Point2 goal{7.5, 0.5};
  const PlanResult first = p.plan(robot, goal);
  ASSERT_TRUE(first.found());
  EXPECT_TRUE(p.tree_growing());
  p.grow_tree();
  ASSERT_TRUE(p.tree_kept());
  for (int dy = 0; dy < 3; ++dy)
    for (int dx = 0; dx < 3; ++dx) p.map().mark_occupied({150 + dx, 55 + dy});  // far off the path
  const PlanResult same = p.plan(robot, goal);
  ASSERT_TRUE(same.found());
  EXPECT_NEAR(same.cost, first.cost, 1e-9);
  EXPECT_LE(same.expanded, 2u);
  // A block on the path 1.2 m ahead: a search near the robot, a fraction of a fresh plan's.
  const Waypoint& ahead = p.waypoints()[25];
  for (int dy = -4; dy <= 4; ++dy)
    for (int dx = -4; dx <= 4; ++dx) p.map().mark_occupied({ahead.cell.x + dx, ahead.cell.y + dy});
  const PlanResult around = p.plan(robot, goal);
  ASSERT_TRUE(around.found());
  EXPECT_NEAR(around.cost, plain(p, robot, goal).cost, 1e-9);
  Planner fresh(cfg);
  fresh.set_map(p.map());
  const PlanResult ref = fresh.plan(robot, goal);
  ASSERT_TRUE(ref.found());
  EXPECT_NEAR(ref.cost, around.cost, 1e-9);
  EXPECT_LT(around.expanded * 3, ref.expanded);
  // A bar across every way ahead: the robot's tree path breaks, the cost rises.
  p.grow_tree();
  for (int y = 0; y < 46; ++y)
    for (int x = 40; x < 43; ++x) p.map().mark_occupied({x, y});
  const PlanResult bar = p.plan(robot, goal);
  ASSERT_TRUE(bar.found());
  EXPECT_NEAR(bar.cost, plain(p, robot, goal).cost, 1e-9);
  EXPECT_GT(bar.cost, around.cost + 1.0);
  EXPECT_GT(bar.expanded, 2u);
}

// Why: a tree that exhausted the goal's states without reaching the robot (new obstacles shut the
// goal's box while it grew) answers "unreachable" at once while the robot stays and costs only
// rise; the robot moving, or a cell clearing, takes a search again. The box's door, once shut,
// leaves a gap the inscribed disc passes and the rectangle does not (else the relaxation alone
// would answer).
TEST(KeptTree, AnExhaustedTreeAnswersUntilTheRobotMovesOrACellClears) {
  const PlannerConfig cfg = rectangle(0.0);
  OccupancyMap base = test::free_map(100, 60);
  for (int i = 60; i <= 90; ++i) {  // a box round the goal
    base.mark_occupied({i, 15});
    base.mark_occupied({i, 45});
  }
  for (int j = 15; j <= 45; ++j) {
    base.mark_occupied({90, j});
    if (j < 22 || j > 38) base.mark_occupied({60, j});  // a door of 17 cells
  }
  base.clear_changes();
  Planner p(cfg);
  p.set_map(base);
  const Pose2 robot{0.5, 1.5, 0.0};
  const Point2 goal{3.75, 1.5};
  ASSERT_TRUE(p.plan(robot, goal).found());
  ASSERT_TRUE(p.tree_growing());
  for (int j = 22; j <= 38; ++j)
    if (j < 28 || j > 33) p.map().mark_occupied({60, j});  // the door narrows to 6 cells (0.30 m)
  p.sync();  // while the tree grows: it goes on
  p.grow_tree();
  ASSERT_TRUE(p.tree_kept());
  const PlanResult shut = p.plan(robot, goal);
  EXPECT_EQ(shut.status, PlanStatus::Unreachable);
  EXPECT_EQ(shut.expanded, 0u);  // the tree's answer
  EXPECT_EQ(plain(p, robot, goal).status, PlanStatus::Unreachable);
  const Pose2 moved{0.75, 1.5, 0.0};
  const PlanResult remade = p.plan(moved, goal);
  EXPECT_EQ(remade.status, PlanStatus::Unreachable);
  EXPECT_GT(remade.expanded, 0u);  // searched again
  for (int j = 22; j <= 38; ++j) p.map().mark_free({60, j});  // the door widens
  const PlanResult open = p.plan(moved, goal);
  ASSERT_TRUE(open.found());
  EXPECT_NEAR(open.cost, plain(p, moved, goal).cost, 1e-9);
}

// Why: the tree's costs were made with a wall standing; once the wall is cleared they no longer
// bound the costs from below (a sync that makes a cell cheaper drops the tree), and the replan
// takes the way through, as a plain search does.
TEST(KeptTree, AWallClearedAfterTheTreeGrewTakesTheWayThrough) {
  OccupancyMap base = test::free_map(80, 60);
  for (int y = 0; y < 56; ++y) base.mark_occupied({40, y});  // a wall with a gap at the top
  base.clear_changes();
  Planner p(rectangle(0.05));
  p.set_map(base);
  const Pose2 robot{0.5, 0.5, 0.0};
  const Point2 goal{3.5, 0.5};
  const PlanResult around = p.plan(robot, goal);
  ASSERT_TRUE(around.found());
  p.grow_tree();
  ASSERT_TRUE(p.tree_kept());
  for (int y = 0; y < 56; ++y) p.map().mark_free({40, y});  // the wall goes
  const PlanResult through = p.plan(robot, goal);
  ASSERT_TRUE(through.found());
  EXPECT_NEAR(through.cost, plain(p, robot, goal).cost, 1e-9);
  EXPECT_LT(through.cost, around.cost - 20.0);
}

// Why: tree_valid()'s memo tags each answer with the replan's epoch, in 7 bits: when the tags
// wrap, answers from 127 replans ago must not pass for current ones. The robot's state is found
// valid at one epoch, a bar then breaks its path while m replans run from beyond the bar (their
// states' paths hold), and the robot comes back, for m round the wrap: its plan still goes round
// the bar (fails when new_epoch() does not clear the memo as the tags wrap).
TEST(KeptTree, TheValidityMemoHoldsAcrossItsTagsWrapping) {
  OccupancyMap base = test::free_map(160, 60);
  for (int y = 0; y < 40; ++y) base.mark_occupied({80, y});
  base.clear_changes();
  const Pose2 a{0.5, 0.5, 0.0};
  const Point2 goal{7.5, 0.5};
  for (const int m : {125, 126, 127, 128, 253, 254, 255}) {
    SCOPED_TRACE(testing::Message() << m << " replans from further on");
    Planner p(rectangle(0.05));
    p.set_map(base);
    ASSERT_TRUE(p.plan(a, goal).found());
    p.grow_tree();
    ASSERT_TRUE(p.tree_kept());
    const PlanResult first = p.plan(a, goal);  // with the tree: the memo says a's path holds
    ASSERT_TRUE(first.found());
    const Pose2 b = along(p, 60);               // beyond the bar below
    ASSERT_GT(p.map().cell_of({b.x, b.y}).x, 45);
    for (int y = 0; y < 46; ++y)                // a bar across every way from a
      for (int x = 40; x < 43; ++x) p.map().mark_occupied({x, y});
    for (int i = 0; i < m; ++i) ASSERT_TRUE(p.plan(b, goal).found());
    ASSERT_TRUE(p.tree_kept());
    const PlanResult back = p.plan(a, goal);
    ASSERT_TRUE(back.found());
    EXPECT_NEAR(back.cost, plain(p, a, goal).cost, 1e-9);
    EXPECT_GT(back.cost, first.cost + 1.0);
  }
}

// Why: two planners on one random 90 x 70 map (seeded), one to plan at once, one in steps.
struct Twins {
  explicit Twins(unsigned seed) : rng(seed), base(random_map(rng, 90, 70, 14, false)), once(cfg), steps(cfg) {
    once.set_map(base);
    steps.set_map(base);
  }
  std::mt19937 rng;                             // the map's draws, then the test's own
  PlannerConfig cfg = rectangle(0.05);          // both planners' configuration
  OccupancyMap base;                            // the map both start from
  Planner once, steps;                          // plans at once, and in steps
};

// Why: the module plans in steps (a field, the tree, the search, one per activation): the same
// plans as at once, round after round of new obstacles and moves.
TEST(KeptTree, InStepsEqualsAtOnce) {
  Twins t(7);
  std::mt19937& rng = t.rng;
  Planner& once = t.once;
  Planner& steps = t.steps;
  Pose2 robot{0.5, 0.5, 0.0};
  const Point2 goal{4.0, 3.0};
  int calls_max = 0;
  for (int round = 0; round < ::robuter::test::sample(16, 6); ++round) {
    SCOPED_TRACE(testing::Message() << "round " << round);
    const PlanResult a = once.plan(robot, goal);
    PlanResult b;
    int calls = 1;
    while (!steps.plan_step(robot, goal, 37, b)) ++calls;
    once.grow_tree();
    while (!steps.grow_tree_step(37)) ++calls;
    calls_max = std::max(calls_max, calls);
    ASSERT_EQ(a.status, b.status);
    if (a.found()) {
      ASSERT_NEAR(a.cost, b.cost, 1e-9);
      ASSERT_EQ(once.waypoints().size(), steps.waypoints().size());
    }
    const Cell c{static_cast<int>(rng() % 90), static_cast<int>(rng() % 70)};
    for (int d = 0; d < 9; ++d) {
      once.map().mark_occupied({std::min(c.x + d % 3, 89), std::min(c.y + d / 3, 69)});
      steps.map().mark_occupied({std::min(c.x + d % 3, 89), std::min(c.y + d / 3, 69)});
    }
    if (a.found() && round % 2 == 0) robot = along(once, 3);
  }
  EXPECT_GT(calls_max, 10);  // the steps were small
}

// Why: the tree's last part (marking its settled states: a walk over every page it used, up to
// 6 ms at once in the seed 000 lab run) goes in steps like its search: after the last state is
// popped, steps of a small budget still follow, the tree not kept until the last; and it answers
// the same replan as a tree grown at once.
TEST(KeptTree, ItsStatesAreSettledInSteps) {
  Twins t(11);
  Planner& once = t.once;
  Planner& steps = t.steps;
  const Pose2 robot{0.5, 0.5, 0.0};
  const Point2 goal{4.0, 3.0};
  ASSERT_TRUE(once.plan(robot, goal).found());
  PlanResult r;
  while (!steps.plan_step(robot, goal, 64, r)) {
  }
  ASSERT_TRUE(r.found());
  once.grow_tree();
  ASSERT_TRUE(once.tree_kept());
  int settling = 0;  // steps after the last pop
  std::uint32_t states = 0;
  while (!steps.grow_tree_step(16)) {
    ASSERT_FALSE(steps.tree_kept());
    if (steps.tree_states() == states && states == once.tree_states()) ++settling;
    states = steps.tree_states();
  }
  EXPECT_TRUE(steps.tree_kept());
  EXPECT_EQ(steps.tree_states(), once.tree_states());
  EXPECT_GE(settling, 2) << steps.tree_pages() << " pages of " << steps.tree_page_states();
  // The same replan after new obstacles on the path.
  for (Planner* p : {&once, &steps}) {
    const auto path = p->waypoints();
    const CellPose c = path[path.size() / 2].cell;
    for (int d = 0; d < 9; ++d) p->map().mark_occupied({c.x + d % 3 - 1, c.y + d / 3 - 1});
  }
  const PlanResult a = once.plan(robot, goal);
  const PlanResult b = steps.plan(robot, goal);
  ASSERT_EQ(a.status, b.status);
  if (a.found()) {
    EXPECT_NEAR(a.cost, b.cost, 1e-9);
  }
  EXPECT_EQ(a.expanded, b.expanded);
}

// Why: the tree's promise, checked state by state: a settled state's value is its exact cost to
// the goal (a plain search from it, with no turn clearance so that both use one turn rule), and
// any state's bound is at most that cost.
TEST(KeptTree, SettledValuesAreExactAndBoundsAreLower) {
  std::mt19937 rng(99);
  const PlannerConfig cfg = rectangle(0.0);
  Planner p(cfg);
  p.set_map(random_map(rng, 70, 50, 10, false));
  std::vector<const PassGrid*> slices;
  for (int k = 0; k < p.slices(); ++k) slices.push_back(&p.expanded(k));
  std::vector<int> move_slice;
  for (int k = 0; k < p.slices(); ++k)
    if (allowed_moves(k, p.slices(), cfg.motion) != 0) move_slice.push_back(k);
  const HeadingOptions opt = options_of(p);
  int settled = 0, bounded = 0;
  for (int trial = 0; trial < ::robuter::test::sample(6, 2); ++trial) {
    const CellPose robot{5 + static_cast<int>(rng() % 20), 5 + static_cast<int>(rng() % 40), static_cast<int>(rng() % 16)};
    const Cell goal{45 + static_cast<int>(rng() % 20), 5 + static_cast<int>(rng() % 40)};
    HeadingSearch tree;
    tree.begin_backward(slices, robot, goal, opt, {}, nullptr, nullptr);
    PlanResult r;
    while (!tree.resume(~std::uint32_t{0}, r)) {
    }
    if (!tree.kept()) continue;
    HeadingSearch one;
    for (int q = 0; q < 300; ++q) {
      const Cell c{static_cast<int>(rng() % 70), static_cast<int>(rng() % 50)};
      const int slot = static_cast<int>(rng() % move_slice.size());
      const int k = move_slice[static_cast<std::size_t>(slot)];
      if (p.expanded(k).at(c) == kBlocked) continue;
      std::uint32_t s = HeadingSearch::kNoState;
      const double b = tree.tree_bound(c.x + 1, c.y + 1, slot, p.expanded(0).index(c), s);
      const PlanResult ref = one.find(slices, CellPose{c.x, c.y, k}, goal, opt);
      const double exact = ref.found() ? ref.cost : CostField::kInfinity;
      if (s != HeadingSearch::kNoState) {
        ++settled;
        ASSERT_NEAR(b, exact, 1e-9) << c.x << "," << c.y << " slice " << k;
      }
      ASSERT_LE(b, exact + 1e-9);
      ++bounded;
    }
  }
  EXPECT_GT(settled, 20);
  EXPECT_GT(bounded, 300);
}

// Why: among paths of equal cost the robot keeps going the way it faces and turns late (what a
// search from the robot finds, and what keeps it in the space it has seen), whatever order the
// tree settled them in: the plan's first straight run from the robot is as long as any optimal
// plan's (one more cell that way, and no optimal path goes on from there). Random boxes, random
// robots and goals, no turn clearance (so that a plain search from a cell on the way has the
// path's own turn rule).
TEST(KeptTree, PathsGoStraightOnFromTheRobotWhereThatCostsNoMore) {
  std::mt19937 rng(5);
  const PlannerConfig cfg = rectangle(0.0);
  const HeadingOptions opt = [&] {
    Planner q(cfg);
    return options_of(q);
  }();
  int checked = 0, runs = 0;
  const int trials = ::robuter::test::sample(120, 30);
  for (int trial = 0; trial < trials; ++trial) {
    Planner p(cfg);
    p.set_map(random_map(rng, 90, 70, 10, false));
    const Pose2 robot{0.3 + 0.05 * static_cast<double>(rng() % 80), 0.3 + 0.05 * static_cast<double>(rng() % 60),
                      kPi / 4 * static_cast<double>(rng() % 8)};
    const Point2 goal{0.3 + 0.05 * static_cast<double>(rng() % 80), 0.3 + 0.05 * static_cast<double>(rng() % 60)};
    if (!p.plan(robot, goal).found()) continue;
    p.grow_tree();
    const PlanResult r = p.plan(robot, goal);  // the kept tree's plan
    if (!r.found()) continue;
    const std::vector<Waypoint>& w = p.waypoints();
    if (w.size() < 2 || !(w[1].cell.slice == w[0].cell.slice)) continue;  // it turns first
    const int dx = w[1].cell.x - w[0].cell.x, dy = w[1].cell.y - w[0].cell.y;
    std::size_t run = 1;
    while (run + 1 < w.size() && w[run + 1].cell.slice == w[0].cell.slice &&
           w[run + 1].cell.x - w[run].cell.x == dx && w[run + 1].cell.y - w[run].cell.y == dy)
      ++run;
    if (run + 1 >= w.size()) continue;  // straight to the goal
    ++runs;
    // One more cell that way: blocked, or no optimal path on from it.
    const int k = w[0].cell.slice;
    const Cell beyond{w[run].cell.x + dx, w[run].cell.y + dy};
    const PassGrid& g = p.expanded(k);
    if (!g.contains(beyond) || g.at(beyond) == kBlocked || g.at(Cell{w[run].cell.x, w[run].cell.y}) == kBlocked) continue;
    if (dx != 0 && dy != 0 &&
        (g.at(Cell{w[run].cell.x + dx, w[run].cell.y}) == kBlocked || g.at(Cell{w[run].cell.x, w[run].cell.y + dy}) == kBlocked))
      continue;
    std::vector<const PassGrid*> slices;
    for (int j = 0; j < p.slices(); ++j) slices.push_back(&p.expanded(j));
    HeadingSearch one;
    const PlanResult on = one.find(slices, CellPose{beyond.x, beyond.y, k}, p.map().cell_of(goal), opt);
    const double step = (dx != 0 && dy != 0) ? kSqrt2 : 1.0;  // free cells: the class costs are 1
    ++checked;
    if (on.found()) {
      EXPECT_GT(static_cast<double>(run + 1) * step + on.cost, r.cost + 1e-6) << "trial " << trial << ": "
          << "going on straight from cell " << w[run].cell.x << "," << w[run].cell.y << " costs no more: run " << run << " d " << dx << "," << dy << " slice " << k << " cost " << r.cost << " on " << on.cost << " robot " << w[0].cell.x << "," << w[0].cell.y << " next " << w[run + 1].cell.x << "," << w[run + 1].cell.y << "/" << w[run + 1].cell.slice;
    }
  }
  EXPECT_GT(runs, trials / 6);  // the sample holds straight runs that end before the goal
  EXPECT_GT(checked, trials / 12);
  std::printf("straight runs %d, checked %d of %d trials\n", runs, checked, trials);
}

}  // namespace
}  // namespace robuter::plan
