// Copying a plan into a PlanSnapshot: bounded loops over preallocated arrays.
#include "modules/planner/lib/plan_snapshot.hpp"

#include <algorithm>

namespace robuter::plan {

void PlanSnapshot::reserve(const Planner& planner, std::size_t max_path) {
  geometry = planner.map().geometry();
  cells.assign(static_cast<std::size_t>(geometry.width) * static_cast<std::size_t>(geometry.height), 0);
  path.assign(std::max<std::size_t>(max_path, 1), Waypoint{});
  path_len = prefix_len = 0;
}

bool PlanSnapshot::capture(const Planner& planner, const PlanResult& result, const Pose2& from, Point2 to) {
  const OccupancyMap& map = planner.map();
  const MapGeometry& g = map.geometry();
  if (g.width != geometry.width || g.height != geometry.height || cells.size() != map.cell_count()) return false;
  geometry = g;
  const int slices = planner.slices();
  for (int y = 0; y < g.height; ++y) {
    for (int x = 0; x < g.width; ++x) {
      const Cell c{x, y};
      int blocked = 0;
      for (int k = 0; k < slices; ++k) blocked += planner.expanded(k).at(c) == kBlocked ? 1 : 0;
      const auto state = static_cast<std::uint8_t>(map.state(c));
      const std::uint8_t layers = blocked == 0 ? 0 : (blocked == slices ? kAllBlocked : kSomeBlocked);
      cells[map.index(c)] = static_cast<std::uint8_t>(state | layers);
    }
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
