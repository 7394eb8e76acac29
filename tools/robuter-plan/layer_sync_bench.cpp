// SPDX-License-Identifier: GPL-3.0-or-later
// robuter-layer-sync-bench: one sync's parts on 320 x 320 (begin_sync, 32 class layers, 32 bit layers) after a 10 x 10 block.
#include <chrono>
#include <cstdio>
#include <random>
#include <algorithm>
#include "modules/planner/lib/cspace.hpp"
#include "modules/planner/lib/footprint.hpp"
using namespace robuter::plan;

// The default window's size, walls on a 240-cell square, the Robuter's rectangle (16 slices over a
// half turn = 32 over the full turn) and its 25 cm turn clearance; each of 30 repetitions builds
// the layers afresh, adds a 10 x 10 block of occupied cells (moved one cell each time) and times
// the sync's three parts; the minimum of each is printed (thread-independent wall time, µs).
using Clock = std::chrono::steady_clock;
static double us(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::micro>(b - a).count(); }
int main() {
  OccupancyMap base(MapGeometry{320, 320, 0.05, {}});
  for (int y = 0; y < 320; ++y) for (int x = 0; x < 320; ++x) base.mark_free({x, y});
  for (int x = 0; x < 320; ++x) { base.mark_occupied({x, 40}); base.mark_occupied({x, 280}); }
  for (int y = 0; y < 320; ++y) { base.mark_occupied({40, y}); base.mark_occupied({280, y}); }
  base.clear_changes();
  RectangleFootprint rect; rect.center_offset = 0.183;
  auto masks = rectangle_slices(rect, 0.05, 32);
  RectangleFootprint grown = rect; grown.margin += 0.25;
  auto tmasks = rectangle_slices(grown, 0.05, 32);
  double tb = 1e9, tc = 1e9, tt = 1e9;
  for (int rep = 0; rep < 30; ++rep) {
    OccupancyMap map = base;
    CSpaceStack st; st.reset(map);
    std::vector<CSpaceLayer> L(32), T(32);
    SliceBits bits; bits.resize(320, 320, 32);
    for (int k = 0; k < 32; ++k) { L[k].build(st, map, masks[k]); T[k].build_bits(st, map, tmasks[k], bits, k); }
    for (int dy = 0; dy < 10; ++dy) for (int dx = 0; dx < 10; ++dx) map.mark_occupied({150 + dx + rep, 150 + dy});
    std::vector<ClassChange> ch; ch.reserve(100000);
    auto t0 = Clock::now();
    st.begin_sync(map, map.changes());
    auto t1 = Clock::now();
    for (int k = 0; k < 32; ++k) L[k].update(st, map, map.changes(), k == 0 ? &ch : nullptr);
    auto t2 = Clock::now();
    for (int k = 0; k < 32; ++k) T[k].update_bits(st, map, map.changes(), bits, k);
    auto t3 = Clock::now();
    st.end_sync(map.changes());
    tb = std::min(tb, us(t0, t1)); tc = std::min(tc, us(t1, t2)); tt = std::min(tt, us(t2, t3));
  }
  std::printf("begin_sync %.1f us, 32 class layers %.1f us, 32 bit layers %.1f us\n", tb, tc, tt);
}
