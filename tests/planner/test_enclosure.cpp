// SPDX-License-Identifier: GPL-3.0-or-later
// The shut-in proof (EnclosureTest) against exhaustive searches, and the search that uses it.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "modules/planner/lib/enclosure.hpp"
#include "modules/planner/lib/heading_search.hpp"
#include "tests/planner/reference_heading_search.hpp"
#include "tests/planner/test_util.hpp"
#include "tests/support/sample.hpp"

namespace robuter::plan {
namespace {

// A stack of K slices over one map: walls of random rooms (so that components are often closed),
// random clutter per slice, turn bits that block a superset of the body's slices (as the
// planner's grown bodies) or only where clutter says.
struct RoomStack {
  std::vector<PassGrid> slices;
  std::vector<PassGrid> turns;
  std::vector<const PassGrid*> slice_ptrs;
  std::vector<const PassGrid*> turn_ptrs;
  SliceBits turn_bits;
};

RoomStack room_stack(std::mt19937& rng, int w, int h, int k) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  PassGrid base(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) base.set({x, y}, u(rng) < 0.2 ? kUnknown : kFree);
  const int walls = 2 + static_cast<int>(rng() % 6);
  for (int i = 0; i < walls; ++i) {  // long straight walls, some with a gap
    const bool vertical = rng() % 2 == 0;
    const int at = static_cast<int>(rng() % static_cast<unsigned>(vertical ? w : h));
    const int len = vertical ? h : w;
    const int gap = rng() % 3 == 0 ? static_cast<int>(rng() % static_cast<unsigned>(len)) : -100;
    const int gap_w = 1 + static_cast<int>(rng() % 4);
    for (int t = 0; t < len; ++t)
      if (t < gap || t >= gap + gap_w) base.set(vertical ? Cell{at, t} : Cell{t, at}, kBlocked);
  }
  RoomStack st;
  st.slices.assign(static_cast<std::size_t>(k), base);
  st.turns.assign(static_cast<std::size_t>(k), base);
  const double clutter = 0.02 + 0.1 * u(rng);
  const bool superset = u(rng) < 0.7;
  for (int s = 0; s < k; ++s)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        PassGrid& g = st.slices[static_cast<std::size_t>(s)];
        if (u(rng) < clutter) g.set({x, y}, kBlocked);
        const bool blocked = (superset && g.at({x, y}) == kBlocked) || u(rng) < clutter;
        st.turns[static_cast<std::size_t>(s)].set({x, y}, blocked ? std::uint8_t{kBlocked} : base.at({x, y}));
      }
  for (const PassGrid& g : st.slices) st.slice_ptrs.push_back(&g);
  for (const PassGrid& g : st.turns) st.turn_ptrs.push_back(&g);
  st.turn_bits = test::slice_bits_of(st.turns);
  return st;
}

// The lean graph's per-slice tables, as HeadingSearch derives them.
struct Tables {
  std::vector<const std::uint8_t*> cls_of;
  std::vector<std::uint8_t> allowed;
  std::vector<int> move_slice;
  std::vector<int> slot_of;
};

Tables tables(const RoomStack& st, MotionModel motion) {
  Tables t;
  const int k = static_cast<int>(st.slices.size());
  for (int s = 0; s < k; ++s) {
    t.cls_of.push_back(st.slices[static_cast<std::size_t>(s)].cls.data());
    t.allowed.push_back(allowed_moves(s, k, motion));
    t.slot_of.push_back(t.allowed.back() != 0 ? static_cast<int>(t.move_slice.size()) : -1);
    if (t.allowed.back() != 0) t.move_slice.push_back(s);
  }
  return t;
}

// Why: "enclosed" is a proof: whenever the flood says the start's component stays inside the
// window without the goal, the exhaustive search of the full (cell x slice) graph — no
// heuristic, so it explores the whole component — finds no path (unreachable, or a goal that no
// slice lets the robot stand on). Random rooms of up to 150 x 150
// cells (larger than the window: the ring must be respected), windows placed at random around
// the start, both motion models, with and without turn bits, starts in pass-through slices.
TEST(EnclosureTest, EnclosedMeansTheExhaustiveSearchFindsNoPath) {
  std::mt19937 rng(20261204);
  const int cases = ::robuter::test::sample(1500, 200);
  int enclosed = 0, open_reachable = 0;
  EnclosureTest test;
  ReferenceHeadingSearch full;
  const std::vector<int> ks = {1, 2, 8, 16, 32, 64, 160};  // 64: turn bits in 2 words; 160: 5 words (the body rule)
  for (int c = 0; c < cases; ++c) {
    const int k = ks[rng() % ks.size()];
    const unsigned side = k > 32 ? 60 : 140;  // many slices: smaller rooms (the reference's cost)
    const int w = 8 + static_cast<int>(rng() % side);
    const int h = 8 + static_cast<int>(rng() % side);
    const RoomStack st = room_stack(rng, w, h, k);
    const MotionModel motion = rng() % 4 == 0 ? MotionModel::Holonomic : MotionModel::Aligned;
    const Tables t = tables(st, motion);
    if (t.move_slice.empty()) continue;
    const bool with_turns = rng() % 2 == 0;
    const CellPose start{static_cast<int>(rng() % static_cast<unsigned>(w)),
                         static_cast<int>(rng() % static_cast<unsigned>(h)), static_cast<int>(rng() % static_cast<unsigned>(k))};
    const Cell goal{static_cast<int>(rng() % static_cast<unsigned>(w)), static_cast<int>(rng() % static_cast<unsigned>(h))};
    if (st.slices[static_cast<std::size_t>(start.slice)].at({start.x, start.y}) == kBlocked) continue;
    const PassGrid& g0 = st.slices[0];
    const LeanGraph lg{t.cls_of.data(), k, g0.stride, g0.height + 2, t.move_slice.data(),
                       static_cast<int>(t.move_slice.size()), t.slot_of.data(), t.allowed.data(),
                       with_turns ? st.turn_bits.bits.data() : nullptr, st.turn_bits.words,
                       g0.index({start.x, start.y}), start.slice, g0.index(goal)};
    test.reserve(static_cast<int>(t.move_slice.size()));
    // The window anywhere that keeps the start (stored at x + 1, y + 1) off its ring.
    const int x0 = start.x - static_cast<int>(rng() % (EnclosureTest::kSize - 2));
    const int y0 = start.y - static_cast<int>(rng() % (EnclosureTest::kSize - 2));
    const bool shut = test.enclosed(lg, x0, y0);
    HeadingOptions opt;
    opt.motion = motion;
    opt.rotation_step_cost = 0.5;
    const PlanResult r = full.find(st.slice_ptrs, start, goal, opt, {}, nullptr,
                                   with_turns ? std::span<const PassGrid* const>(st.turn_ptrs)
                                              : std::span<const PassGrid* const>());
    SCOPED_TRACE(testing::Message() << "case " << c << " k " << k << " " << w << "x" << h);
    if (shut) {
      ++enclosed;
      ASSERT_FALSE(r.found()) << "enclosed, but the search found a way out (start " << start.x << ","
                              << start.y << "," << start.slice << ", window at " << x0 << "," << y0 << ")";
    } else if (r.found()) {
      ++open_reachable;
    }
  }
  EXPECT_GT(enclosed, cases / 10);
  EXPECT_GT(open_reachable, cases / 10);
}

// Why: the case that made unreachable replans slow (docs/PLANNER.md, "Shut in"): a new block
// shuts the robot into a room of 3 x 4 m; the goal is beyond the room's wall. The search used to
// exhaust every state of the room (thousands) before saying "unreachable"; it now stops after
// kEnclosureAfter expansions with the flood's proof, with the same status as the reference.
TEST(EnclosureTest, ASearchShutInARoomEndsEarlyWithTheSameAnswer) {
  const int w = 200, h = 200, k = 32;
  PassGrid room(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) room.set({x, y}, kFree);
  for (int t = 20; t <= 100; ++t) {  // walls of a 60 x 80 cell room, no door
    room.set({20, t}, kBlocked);
    room.set({80, t}, kBlocked);
  }
  for (int t = 20; t <= 80; ++t) {
    room.set({t, 20}, kBlocked);
    room.set({t, 100}, kBlocked);
  }
  std::vector<const PassGrid*> stack(k, &room);
  HeadingOptions opt;
  opt.rotation_step_cost = 0.5;
  HeadingSearch search;
  const PlanResult r = search.find(stack, CellPose{50, 60, 0}, Cell{150, 150}, opt);
  EXPECT_EQ(r.status, PlanStatus::Unreachable);
  EXPECT_TRUE(search.ended_shut_in());
  EXPECT_LT(r.expanded, 2 * HeadingSearch::kEnclosureAfter);
  ReferenceHeadingSearch full;
  const PlanResult ref = full.find(stack, CellPose{50, 60, 0}, Cell{150, 150}, opt);
  EXPECT_EQ(ref.status, PlanStatus::Unreachable);
  EXPECT_GT(ref.expanded, 10000u);  // what the search used to pay
  // A door in the room's wall: the flood leaves the room; the search finds the way.
  for (int t = 50; t < 62; ++t) room.set({80, t}, kFree);
  const PlanResult out = search.find(stack, CellPose{50, 60, 0}, Cell{150, 150}, opt);
  EXPECT_TRUE(out.found());
  EXPECT_FALSE(search.ended_shut_in());
}

}  // namespace
}  // namespace robuter::plan
