// SPDX-License-Identifier: GPL-3.0-or-later
// Exactness of the shared-occupancy C-space layers: incremental updates equal a fresh full build.
#include <gtest/gtest.h>

#include <array>
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
// once, with the class it had before.
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
      stack.end_sync(map.changes());
      map.clear_changes();
      for (std::size_t k = 0; k < layers.size(); ++k) {
        CSpaceLayer fresh;
        fresh.build(map, masks[k]);
        for (std::uint8_t c : fresh.grid().cls) ++seen[c];
        ASSERT_EQ(layers[k].grid().cls, fresh.grid().cls) << "map " << w << "x" << h << " batch " << batch
                                                            << " layer " << k;
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

// Why: the facade's wiring: after random syncs its body and turn layers equal those of a planner
// given the final map at once.
TEST(CSpaceStack, PlannerLayersAfterSyncsEqualAFreshPlanner) {
  PlannerConfig cfg;
  cfg.footprint = FootprintKind::Rectangle;
  cfg.rectangle = RectangleFootprint{1.025, 0.700, 0.183, 0.0};
  cfg.turn_clearance = 0.25;
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
  ASSERT_EQ(p.slices(), 32);
  for (int k = 0; k < p.slices(); ++k) {
    EXPECT_EQ(p.expanded(k).cls, fresh.expanded(k).cls) << "slice " << k;
    EXPECT_EQ(p.turnable(k).cls, fresh.turnable(k).cls) << "slice " << k;
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
