// SPDX-License-Identifier: GPL-3.0-or-later
// World files into planner maps: the simulator's loader, then the edges rasterised.
#include "tools/robuter-plan/world_map.hpp"

#include <cmath>

#include "hal/sim/world_io.hpp"
#include "modules/planner/lib/bresenham.hpp"

namespace robuter::plan::tool {

void rasterise_world(const sim::World& world, OccupancyMap& map) {
  for (const sim::Segment& e : world.segments()) {
    const Cell a = map.cell_of(Point2{e.a.x(), e.a.y()});
    const Cell b = map.cell_of(Point2{e.b.x(), e.b.y()});
    for_each_line_cell(a, b, [&](int x, int y) {
      if (map.contains({x, y})) map.mark_occupied({x, y});
      return true;
    });
  }
}

Result<WorldMap> load_world_map(const std::string& path, double resolution, double margin) {
  auto loaded = sim::load_world(path);
  if (!loaded) return Error{loaded.error().file, loaded.error().line, loaded.error().message};
  const sim::World& world = loaded.value();
  const sim::Box& b = world.bounds();
  const double x0 = std::floor((b.lo.x() - margin) / resolution) * resolution;
  const double y0 = std::floor((b.lo.y() - margin) / resolution) * resolution;
  const double cols = std::ceil((b.hi.x() + margin - x0) / resolution - 1e-9);
  const double rows = std::ceil((b.hi.y() + margin - y0) / resolution - 1e-9);
  if (!(cols >= 1 && rows >= 1) || cols * rows > 16e6)
    return Error{path, 0, "world too large for a map: more than 16 million cells"};
  WorldMap out;
  out.map = OccupancyMap(MapGeometry{static_cast<int>(cols), static_cast<int>(rows), resolution, Point2{x0, y0}});
  rasterise_world(world, out.map);
  out.map.clear_changes();
  if (world.start) out.start = Pose2{world.start->x, world.start->y, world.start->theta};
  if (world.goal) out.goal = Point2{world.goal->x(), world.goal->y()};
  return out;
}

}  // namespace robuter::plan::tool
