// SPDX-License-Identifier: GPL-3.0-or-later
// Beams from the ring's mounts, and the body's cells, in world cells.
#include "modules/planner/sonar_mapping.hpp"

#include <algorithm>
#include <cmath>

namespace robuter::planner {

namespace {
// How much a cell looks like the surface that echoed: net hits (a count above the map's
// initial count) more than an unknown cell, an unknown cell more than one with no net hits.
int evidence(std::uint8_t count, std::uint8_t initial) {
  if (count == plan::OccupancyMap::kUnknown) return 2 * initial + 1;
  return 2 * count;
}
}  // namespace

// The echo came from the nearest surface somewhere in the cone, at `range`: on the arc. The hit
// goes to the arc's cell (or the cell half a cell beyond it) with the most evidence of an
// obstacle, the one nearest the axis among equals (so with nothing known it is the axis, seed
// 003's rule). Cells before the echo along
// the axis and along the chosen ray lose a hit.
void integrate_reading(plan::OccupancyMap& map, const plan::Pose2& robot, const SensorMount& mount,
                       double range, bool no_echo, double beam_range, double half_angle) {
  if (!(range > 0.0) || !(beam_range > 0.0)) return;  // no data (also NaN)
  const double c = std::cos(robot.heading), s = std::sin(robot.heading);
  const plan::Point2 origin{robot.x + c * mount.x - s * mount.y, robot.y + s * mount.x + c * mount.y};
  const double axis = robot.heading + mount.direction;
  if (no_echo || range >= beam_range) {  // nothing within beam_range (or a shortened firing's reach): misses only
    const double reach = no_echo ? std::min(range, beam_range) : beam_range;
    map.integrate_beam(origin, axis, reach, reach);
    return;
  }
  double best_phi = 0.0;
  double best_range = range;
  if (half_angle > 0.0) {
    // A quarter of a cell along the arc: a jamb's corner touches the arc at one point, and the
    // corner cell crosses the arc half a cell further over less than a cell's width; a step of
    // a whole cell missed it and put the hit in the free cell beside it, narrowing a 90 cm
    // door by 5 cm (PlannerSimPriorMap.TheRingsEchoesFromTheJambsDoNotCloseTheDoor).
    const double step = 0.25 * map.resolution() / range;
    const int steps = static_cast<int>(std::min(half_angle / step, 400.0));
    // The surface touches the arc from beyond: a face on a cell boundary met at the arc lies in
    // the cell half a cell further, which a prior map (or earlier hits) knows as the obstacle.
    // Each ray's cell on the arc is looked at first, then that one.
    const double reach[2] = {range, range + 0.5 * map.resolution()};
    int best = -1;
    for (int i = 0; i <= 2 * steps; ++i) {
      const double phi = (i % 2 == 0 ? 1.0 : -1.0) * ((i + 1) / 2) * step;  // 0, -1, +1, -2, +2, ... steps
      for (const double r : reach) {
        const plan::Cell cell = map.cell_of({origin.x + r * std::cos(axis + phi), origin.y + r * std::sin(axis + phi)});
        if (!map.contains(cell)) continue;
        const int e = evidence(map.count(cell), map.initial_count());
        if (e > best) {
          best = e;
          best_phi = phi;
          best_range = r;
        }
      }
    }
  }
  const double clear = range - 2.0 * map.resolution();  // stop short of the surface's cell
  if (best_phi != 0.0 && clear > 0.0) map.integrate_beam(origin, axis, clear, clear);
  map.integrate_beam(origin, axis + best_phi, best_range, beam_range);
}

SensorMount pan_tilt_mount(const robot::PanTiltMount& mount, double direction) {
  const double face = mount.face_offset;
  return SensorMount{mount.pivot_x + face * std::cos(direction), face * std::sin(direction), direction};
}

// Cells whose centre lies inside the rectangle (a cell only partly under the body keeps what the
// sonar said about it: an obstacle may touch the body's edge).
void mark_body_free(plan::OccupancyMap& map, const plan::Pose2& robot, const robot::Body& body) {
  const double c = std::cos(robot.heading), s = std::sin(robot.heading);
  const double cx = robot.x + c * body.center_ahead(), cy = robot.y + s * body.center_ahead();
  const double hl = 0.5 * body.length, hw = 0.5 * body.width;
  const double ex = std::abs(c) * hl + std::abs(s) * hw, ey = std::abs(s) * hl + std::abs(c) * hw;
  const plan::Cell lo = map.cell_of({cx - ex, cy - ey});
  const plan::Cell hi = map.cell_of({cx + ex, cy + ey});
  for (int y = std::max(lo.y, 0); y <= std::min(hi.y, map.height() - 1); ++y) {
    for (int x = std::max(lo.x, 0); x <= std::min(hi.x, map.width() - 1); ++x) {
      const plan::Point2 p = map.center({x, y});
      const double dx = p.x - cx, dy = p.y - cy;
      const double along = dx * c + dy * s, across = -dx * s + dy * c;
      if (std::abs(along) <= hl && std::abs(across) <= hw && map.count({x, y}) != 0) map.mark_free({x, y});
    }
  }
}

}  // namespace robuter::planner
