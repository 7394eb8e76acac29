// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers shared by the planner tests: grids from ASCII art, temporary files.
#pragma once

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/planner/lib/pass_grid.hpp"
#include "modules/planner/lib/slice_bits.hpp"

namespace robuter::plan::test {

// Why: small hand-made grids read best as pictures; rows are given top (largest y) first.
// '#' blocked, '?' unknown, anything else free.
inline PassGrid grid_from_art(const std::vector<std::string>& rows) {
  const int h = static_cast<int>(rows.size());
  const int w = static_cast<int>(rows[0].size());
  PassGrid g(w, h);
  for (int r = 0; r < h; ++r)
    for (int x = 0; x < w; ++x) {
      const char c = rows[static_cast<std::size_t>(r)][static_cast<std::size_t>(x)];
      g.set({x, h - 1 - r}, c == '#' ? kBlocked : c == '?' ? kUnknown : kFree);
    }
  return g;
}

// Why: turn-room grids (one per slice) as the planner keeps them: one bit per slice and cell,
// set where the slice's grid is blocked.
inline SliceBits slice_bits_of(const std::vector<PassGrid>& turns) {
  SliceBits bits;
  if (turns.empty()) return bits;
  const int k = static_cast<int>(turns.size());
  bits.resize(turns[0].width, turns[0].height, k);
  for (int s = 0; s < k; ++s)
    for (std::uint32_t i = 0; i < turns[static_cast<std::size_t>(s)].cls.size(); ++i)
      bits.set_blocked(i, s, turns[static_cast<std::size_t>(s)].cls[i] == kBlocked);
  return bits;
}

// Why: an open map (every cell known free) of w x h cells of 5 cm, for facade tests.
inline OccupancyMap free_map(int w, int h) {
  OccupancyMap map(MapGeometry{w, h, 0.05, {}});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) map.mark_free({x, y});
  return map;
}

// Why: loaders are tested through real files too; this writes one under /tmp.
inline std::string temp_file(const std::string& name, const std::string& text) {
  const std::string path = "/tmp/robuter-planner-test-" + std::to_string(::getpid()) + "-" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

}  // namespace robuter::plan::test
