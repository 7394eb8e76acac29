// SPDX-License-Identifier: GPL-3.0-or-later
// Exactness of the shared-occupancy C-space layers: incremental updates equal a fresh full build.
#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <map>
#include <random>
#include <set>

#include "modules/planner/lib/cspace.hpp"
#include "modules/planner/lib/cspace_stack.hpp"
#include "modules/planner/lib/footprint.hpp"
#include "modules/planner/lib/planner.hpp"

namespace robuter::plan {
namespace {

// The firmware's default masks at 5 cm: 32 full-turn body slices (centre 183 mm ahead of the
// axle), the same grown by a 25 cm turn clearance, and the inscribed disc.
std::vector<FootprintMask> default_masks() {
  const RectangleFootprint body{1.025, 0.700, 0.183, 0.0};
  std::vector<FootprintMask> masks = rectangle_slices(body, 0.05, 32);
  RectangleFootprint grown = body;
  grown.margin += 0.25;
  for (FootprintMask& m : rectangle_slices(grown, 0.05, 32)) masks.push_back(std::move(m));
  masks.push_back(disc_mask(inscribed_radius(body), 0.05));
  return masks;
}

// Why: one random batch of map changes, biased to the map's edges: new obstacles, obstacles
// freed, unknown <-> free, cells changed twice, small blobs. The masks are wide (up to ~35 cells),
// so the obstacles are kept few (about `target` cells) for the layers to keep free and unknown
// cells: freeing picks existing obstacles.
void random_batch(OccupancyMap& map, std::mt19937& rng, int changes, int target) {
  const int w = map.width(), h = map.height();
  std::uniform_int_distribution<int> cx(0, w - 1), cy(0, h - 1), pick(0, 99), edge(0, 3);
  auto any_cell = [&]() -> Cell {
    Cell c{cx(rng), cy(rng)};
    if (pick(rng) < 25) {  // on an edge row or column
      switch (edge(rng)) {
        case 0: c.x = 0; break;
        case 1: c.x = w - 1; break;
        case 2: c.y = 0; break;
        default: c.y = h - 1; break;
      }
    }
    return c;
  };
  auto obstacles = [&]() {
    int n = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) n += map.state({x, y}) == CellState::Occupied;
    return n;
  };
  auto an_obstacle = [&]() -> Cell {
    for (int tries = 0; tries < 20000; ++tries) {
      const Cell c{cx(rng), cy(rng)};
      if (map.state(c) == CellState::Occupied) return c;
    }
    return any_cell();
  };
  for (int k = 0; k < changes; ++k) {
    const bool grow = obstacles() < target;
    const int v = pick(rng);
    if (v < 30) {
      if (grow) map.mark_occupied(any_cell());                          // a new obstacle
      else if (pick(rng) < 70) map.mark_free(an_obstacle());            // an obstacle freed
      else map.set_count(an_obstacle(), OccupancyMap::kUnknown);        // an obstacle forgotten
    } else if (v < 60) {
      map.mark_free(any_cell());                                        // unknown -> free (or freed)
    } else if (v < 72) {
      const Cell c = any_cell();                                        // free -> unknown
      if (map.state(c) != CellState::Occupied) map.set_count(c, OccupancyMap::kUnknown);
    } else if (v < 80) {                                                // toggled twice
      const Cell c = any_cell();
      const std::uint8_t was = map.count(c);
      map.mark_occupied(c);
      map.set_count(c, was);
    } else if (v < 88) {                                                // freed and back
      const Cell c = an_obstacle();
      map.mark_free(c);
      map.mark_occupied(c);
      if (pick(rng) < 40) map.set_count(c, OccupancyMap::kUnknown);
    } else {                                                            // a small blob
      const bool blob_occ = grow;
      const Cell c = blob_occ ? any_cell() : an_obstacle();
      const int side = 1 + pick(rng) % 3;
      for (int dy = -1; dy < side; ++dy)
        for (int dx = -1; dx < side; ++dx) {
          const Cell d{c.x + dx, c.y + dy};
          if (!map.contains(d)) continue;
          if (blob_occ) map.mark_occupied(d);
          else if (map.state(d) == CellState::Occupied) map.mark_free(d);
        }
    }
  }
}

// Why: every layer, after many batches of incremental updates, must equal a fresh full build of
// the same map, and each update's report must list exactly the cells whose class changed, each
// once, with the class it had before. The 32 turn masks are also kept as bit layers (as the
// planner keeps them): after each batch their bits equal a fresh bit build and, cell by cell,
// "blocked" of the fresh class layer of the same mask.
TEST(CSpaceStack, IncrementalUpdatesEqualAFreshBuild) {
  const std::vector<FootprintMask> masks = default_masks();
  ASSERT_EQ(masks.size(), 65u);
  for (const auto& [w, h, seed] : std::vector<std::tuple<int, int, unsigned>>{{96, 72, 1}, {44, 110, 2}, {150, 24, 3}}) {
    OccupancyMap map(MapGeometry{w, h, 0.05, {}});
    std::mt19937 rng(seed);
    for (int y = 0; y < h; ++y)  // a partly known map to start from
      for (int x = 0; x < w; ++x)
        if ((x / 9 + y / 7) % 3 != 0) map.mark_free({x, y});
    random_batch(map, rng, 60, 12);
    map.clear_changes();
    CSpaceStack stack;
    stack.reset(map);
    std::vector<CSpaceLayer> layers(masks.size());
    for (std::size_t k = 0; k < masks.size(); ++k) layers[k].build(map, masks[k]);
    constexpr int kTurnFirst = 32;  // masks[32, 64): the turn clearance's grown bodies
    constexpr int kTurns = 32;
    SliceBits bits;
    bits.resize(w, h, kTurns);
    std::vector<CSpaceLayer> bit_layers(kTurns);
    for (int k = 0; k < kTurns; ++k) bit_layers[static_cast<std::size_t>(k)].build_bits(map, masks[static_cast<std::size_t>(kTurnFirst + k)], bits, k);
    std::vector<ClassChange> out;
    std::array<std::size_t, 3> seen{};  // stored cells per class over all checks
    std::size_t changes_seen = 0;       // reported class changes over all batches
    for (int batch = 0; batch < 25; ++batch) {
      std::uniform_int_distribution<int> size(1, batch % 5 == 0 ? 80 : 12);
      random_batch(map, rng, size(rng), 12);
      std::vector<std::vector<std::uint8_t>> before(layers.size());
      for (std::size_t k = 0; k < layers.size(); ++k) before[k] = layers[k].grid().cls;
      stack.begin_sync(map, map.changes());
      std::vector<std::vector<ClassChange>> reports(layers.size());
      for (std::size_t k = 0; k < layers.size(); ++k) {
        out.assign(3, ClassChange{0, 0});  // a report appends after what the caller holds
        layers[k].update(stack, map, map.changes(), &out);
        for (std::size_t i = 0; i < 3; ++i) ASSERT_EQ(out[i].index, 0u);
        reports[k].assign(out.begin() + 3, out.end());
        changes_seen += reports[k].size();
      }
      for (int k = 0; k < kTurns; ++k)
        bit_layers[static_cast<std::size_t>(k)].update_bits(stack, map, map.changes(), bits, k);
      stack.end_sync(map.changes());
      map.clear_changes();
      SliceBits fresh_bits;
      fresh_bits.resize(w, h, kTurns);
      for (int k = 0; k < kTurns; ++k) {
        CSpaceLayer f;
        f.build_bits(map, masks[static_cast<std::size_t>(kTurnFirst + k)], fresh_bits, k);
      }
      ASSERT_EQ(bits.bits, fresh_bits.bits) << "map " << w << "x" << h << " batch " << batch << " turn bits";
      for (std::size_t k = 0; k < layers.size(); ++k) {
        CSpaceLayer fresh;
        fresh.build(map, masks[k]);
        for (std::uint8_t c : fresh.grid().cls) ++seen[c];
        ASSERT_EQ(layers[k].grid().cls, fresh.grid().cls) << "map " << w << "x" << h << " batch " << batch
                                                            << " layer " << k;
        const int turn = static_cast<int>(k) - kTurnFirst;
        if (turn >= 0 && turn < kTurns) {
          for (std::uint32_t g = 0; g < fresh.grid().cls.size(); ++g) {
            ASSERT_EQ(bits.blocked_at(g, turn), fresh.grid().cls[g] == kBlocked) << "turn bit " << turn << " cell " << g;
          }
        }
        std::map<std::uint32_t, std::uint8_t> reported;
        for (const ClassChange& ch : reports[k])
          ASSERT_TRUE(reported.emplace(ch.index, ch.before).second) << "reported twice, layer " << k;
        for (std::uint32_t g = 0; g < before[k].size(); ++g) {
          const bool changed = before[k][g] != layers[k].grid().cls[g];
          const auto it = reported.find(g);
          ASSERT_EQ(changed, it != reported.end()) << "layer " << k << " stored cell " << g;
          if (changed) {
            ASSERT_EQ(it->second, before[k][g]);
          }
        }
      }
    }
    // The check saw every class and many changes (a map blocked everywhere would prove nothing).
    EXPECT_GT(seen[kFree], seen[kBlocked] / 10) << w << "x" << h;
    EXPECT_GT(seen[kUnknown], seen[kBlocked] / 10) << w << "x" << h;
    EXPECT_GT(changes_seen, 100000u) << w << "x" << h;
  }
}

// Why: a block of new obstacles (what a scan finds ahead) goes by the update's window of bits
// (CSpaceLayer), not by runs: at the map's corners and edges, inside, over old obstacles, with
// cells freed and forgotten in the same batch, and a batch too spread for the window (by runs).
// Every class layer and turn bit layer equals a fresh build after each batch, and both paths ran.
TEST(CSpaceStack, BlocksOfNewObstaclesEqualAFreshBuild) {
  const std::vector<FootprintMask> masks = default_masks();
  constexpr int kTurnFirst = 32;
  constexpr int kTurns = 32;
  const int w = 130, h = 90;
  OccupancyMap map(MapGeometry{w, h, 0.05, {}});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if ((x / 11 + y / 8) % 3 != 0) map.mark_free({x, y});
  for (const Cell c : {Cell{60, 40}, Cell{61, 40}, Cell{20, 70}, Cell{100, 12}}) map.mark_occupied(c);
  map.clear_changes();
  CSpaceStack stack;
  stack.reset(map);
  std::vector<CSpaceLayer> layers(masks.size());
  for (std::size_t k = 0; k < masks.size(); ++k) layers[k].build(map, masks[k]);
  SliceBits bits;
  bits.resize(w, h, kTurns);
  std::vector<CSpaceLayer> bit_layers(kTurns);
  for (int k = 0; k < kTurns; ++k)
    bit_layers[static_cast<std::size_t>(k)].build_bits(map, masks[static_cast<std::size_t>(kTurnFirst + k)], bits, k);
  auto block = [&](int x0, int y0, int side) {
    for (int y = y0; y < y0 + side; ++y)
      for (int x = x0; x < x0 + side; ++x)
        if (map.contains({x, y})) map.mark_occupied({x, y});
  };
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> rx(0, w - 1), ry(0, h - 1);
  const std::vector<std::function<void()>> batches = {
      [&] { block(0, 0, 10); },                   // a corner
      [&] { block(w - 10, h - 10, 10); },         // the opposite corner
      [&] { block(-4, 40, 10); },                 // cut by the west edge
      [&] { block(55, h - 6, 10); },              // cut by the north edge
      [&] { block(56, 36, 10); },                 // over old obstacles
      [&] {                                       // a block with cells freed and forgotten
        block(30, 20, 10);
        map.mark_free({60, 40});
        map.set_count({20, 70}, OccupancyMap::kUnknown);
        map.mark_free({3, 3});
      },
      [&] {                                       // a ragged block, holes and a spur
        block(85, 50, 10);
        map.mark_free({88, 53});
        map.mark_free({90, 55});
        for (int x = 95; x < 105; ++x) map.mark_occupied({x, 52});
      },
      [&] {                                       // spread single cells: by runs
        for (int k = 0; k < 6; ++k) map.mark_occupied({rx(rng), ry(rng)});
      },
  };
  std::size_t windows_before = 0;
  for (std::size_t b = 0; b < batches.size(); ++b) {
    batches[b]();
    windows_before = stack.windows();
    stack.begin_sync(map, map.changes());
    std::vector<ClassChange> out;
    for (CSpaceLayer& l : layers) l.update(stack, map, map.changes(), &out);
    for (int k = 0; k < kTurns; ++k)
      bit_layers[static_cast<std::size_t>(k)].update_bits(stack, map, map.changes(), bits, k);
    stack.end_sync(map.changes());
    map.clear_changes();
    if (b + 1 < batches.size()) {
      EXPECT_GE(stack.windows(), windows_before + masks.size()) << "batch " << b << " went by runs";
    } else {
      EXPECT_EQ(stack.windows(), windows_before) << "spread cells went by the window";
    }
    SliceBits fresh_bits;
    fresh_bits.resize(w, h, kTurns);
    for (int k = 0; k < kTurns; ++k) {
      CSpaceLayer f;
      f.build_bits(map, masks[static_cast<std::size_t>(kTurnFirst + k)], fresh_bits, k);
    }
    ASSERT_EQ(bits.bits, fresh_bits.bits) << "batch " << b << " turn bits";
    for (std::size_t k = 0; k < layers.size(); ++k) {
      CSpaceLayer fresh;
      fresh.build(map, masks[k]);
      ASSERT_EQ(layers[k].grid().cls, fresh.grid().cls) << "batch " << b << " layer " << k;
    }
  }
}

// Why: the facade's wiring: after random syncs its body and turn layers equal those of a planner
// given the final map at once, and each turn bit says what a class layer of the grown body says;
// at 16 and 64 slices over a half turn (32 and 128 turn bits per cell: 1 and 4 words).
TEST(CSpaceStack, PlannerLayersAfterSyncsEqualAFreshPlanner) {
  for (const int half_turn : {16, 64}) {
    PlannerConfig cfg;
    cfg.footprint = FootprintKind::Rectangle;
    cfg.rectangle = RectangleFootprint{1.025, 0.700, 0.183, 0.0};
    cfg.turn_clearance = 0.25;
    cfg.heading_slices = half_turn;
    Planner p(cfg);
    OccupancyMap start(MapGeometry{60, 45, 0.05, {}});
    std::mt19937 rng(9);
    for (int y = 0; y < 45; ++y)
      for (int x = 0; x < 60; ++x)
        if ((x / 9 + y / 7) % 3 != 0) start.mark_free({x, y});
    random_batch(start, rng, 30, 6);
    start.clear_changes();
    p.set_map(start);
    for (int batch = 0; batch < 15; ++batch) {
      random_batch(p.map(), rng, 10, 6);
      p.sync();
    }
    Planner fresh(cfg);
    fresh.set_map(p.map());
    ASSERT_EQ(p.slices(), 2 * half_turn);
    ASSERT_EQ(p.turn_room().slices, 2 * half_turn);
    ASSERT_EQ(p.turn_room().words, (2 * half_turn + 31) / 32);
    EXPECT_EQ(p.turn_room().bits, fresh.turn_room().bits);
    RectangleFootprint grown = cfg.rectangle;
    grown.margin += cfg.turn_clearance;
    const std::vector<FootprintMask> turn_masks = rectangle_slices(grown, 0.05, p.slices());
    std::size_t blocked = 0, clear = 0;
    for (int k = 0; k < p.slices(); ++k) {
      EXPECT_EQ(p.expanded(k).cls, fresh.expanded(k).cls) << "slice " << k;
      CSpaceLayer grown_layer;
      grown_layer.build(p.map(), turn_masks[static_cast<std::size_t>(k)]);
      for (int y = -1; y <= 45; ++y)
        for (int x = -1; x <= 60; ++x) {
          const Cell c{x, y};
          const bool b = grown_layer.grid().at(c) == kBlocked;
          ASSERT_EQ(p.turn_room().blocked(c, k), b) << "slice " << k << " cell " << x << "," << y;
          ASSERT_EQ(p.can_turn(c, k), !b) << "slice " << k << " cell " << x << "," << y;
          (b ? blocked : clear) += 1;
        }
    }
    EXPECT_GT(clear, blocked / 10);  // room to turn somewhere, not a map blocked everywhere
  }
}

// Why: the disc planner's one layer after syncs equals a fresh build, and its incremental cost
// field, repaired from the layer's reports at every sync, gives the plan a fresh planner gives.
TEST(CSpaceStack, DiscPlannerAfterSyncsEqualsAFreshPlanner) {
  PlannerConfig cfg;
  cfg.footprint = FootprintKind::Disc;
  cfg.radius = 0.30;
  cfg.unknown_cost = 1.5;
  Planner p(cfg);
  OccupancyMap start(MapGeometry{60, 45, 0.05, {}});
  for (int y = 0; y < 45; ++y)
    for (int x = 0; x < 60; ++x)
      if ((x / 9 + y / 7) % 3 != 0) start.mark_free({x, y});
  std::mt19937 rng(21);
  random_batch(start, rng, 30, 10);
  start.clear_changes();
  p.set_map(start);
  const Pose2 from{0.3, 0.3, 0.0};
  const Point2 goal{2.7, 1.9};
  for (int batch = 0; batch < 30; ++batch) {
    p.plan(from, goal);  // the field to the goal exists, later syncs repair it
    random_batch(p.map(), rng, 8, 10);
    p.sync();
    Planner fresh(cfg);
    fresh.set_map(p.map());
    ASSERT_EQ(p.expanded(0).cls, fresh.expanded(0).cls) << "batch " << batch;
    const PlanResult a = p.plan(from, goal);
    const PlanResult b = fresh.plan(from, goal);
    ASSERT_EQ(a.status, b.status) << "batch " << batch;
    if (a.found()) {
      ASSERT_NEAR(a.cost, b.cost, 1e-9) << "batch " << batch;
    }
  }
}

}  // namespace
}  // namespace robuter::plan
