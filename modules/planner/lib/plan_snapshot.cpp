// SPDX-License-Identifier: GPL-3.0-or-later
// Copying a plan into a PlanSnapshot: bounded loops over preallocated arrays.
#include "modules/planner/lib/plan_snapshot.hpp"

#include <algorithm>

namespace robuter::plan {

void PlanSnapshot::reserve(const Planner& planner, std::size_t max_path) {
  geometry = planner.map().geometry();
  cells.assign(static_cast<std::size_t>(geometry.width) * static_cast<std::size_t>(geometry.height), 0);
  blocked.assign(cells.size(), 0);
  path.assign(std::max<std::size_t>(max_path, 1), Waypoint{});
  path_len = prefix_len = 0;
}

bool PlanSnapshot::capture(const Planner& planner, const PlanResult& result, const Pose2& from, Point2 to) {
  const OccupancyMap& map = planner.map();
  const MapGeometry& g = map.geometry();
  if (g.width != geometry.width || g.height != geometry.height || cells.size() != map.cell_count() ||
      blocked.size() != cells.size())
    return false;
  geometry = g;
  // Layer by layer along the stored rows (the layers are read in memory order, not through
  // a per-cell index): blocked[] counts, per cell, the slices that block it.
  const int slices = planner.slices();
  std::fill(blocked.begin(), blocked.end(), std::uint16_t{0});
  const auto wd = static_cast<std::size_t>(g.width);
  for (int k = 0; k < slices; ++k) {
    const PassGrid& grid = planner.expanded(k);
    for (int y = 0; y < g.height; ++y) {
      const std::uint8_t* row = grid.cls.data() + grid.index({0, y});
      std::uint16_t* out = blocked.data() + static_cast<std::size_t>(y) * wd;
      for (std::size_t x = 0; x < wd; ++x) out[x] = static_cast<std::uint16_t>(out[x] + (row[x] == kBlocked ? 1 : 0));
    }
  }
  const auto all = static_cast<std::uint16_t>(slices);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const auto state = static_cast<std::uint8_t>(map.state_at(static_cast<std::uint32_t>(i)));
    const std::uint8_t layers = blocked[i] == 0 ? 0 : (blocked[i] >= all ? kAllBlocked : kSomeBlocked);
    cells[i] = static_cast<std::uint8_t>(state | layers);
  }
  const auto& w = planner.waypoints();
  path_len = result.found() ? std::min(w.size(), path.size()) : 0;
  path_truncated = result.found() && w.size() > path.size();
  std::copy_n(w.begin(), path_len, path.begin());
  prefix_len = 0;  // the caller sets it after the capture (the module knows its prefix)
  footprint = planner.config().footprint;
  rectangle = planner.config().rectangle;
  radius = planner.config().radius;
  start = from;
  goal = to;
  status = result.status;
  length = result.found() ? result.length * g.resolution : 0.0;
  return true;
}

}  // namespace robuter::plan
