// SPDX-License-Identifier: GPL-3.0-or-later
// Visible prefix, legs and the blocked check.
#include "modules/planner/route.hpp"

#include <cmath>

#include "modules/planner/lib/bresenham.hpp"
#include "modules/planner/lib/pass_grid.hpp"

namespace robuter::planner {

namespace {
// The value of `a` + 2πn nearest to `near`.
double nearest_turn(double a, double near) {
  return a + 2.0 * plan::kPi * std::round((near - a) / (2.0 * plan::kPi));
}

// True when the straight line between the cells meets no obstacle cell of the map.
bool seen(const plan::OccupancyMap& map, plan::Cell from, plan::Cell to) {
  bool clear = true;
  plan::for_each_line_cell(from, to, [&](int x, int y) {
    const plan::Cell c{x, y};
    if (map.contains(c) && map.state(c) == plan::CellState::Occupied) clear = false;
    return clear;
  });
  return clear;
}
}  // namespace

std::size_t visible_prefix(const plan::OccupancyMap& map, std::span<const plan::Waypoint> path, plan::Point2 robot,
                           double range) {
  if (path.empty()) return 0;
  const plan::Cell rc = map.cell_of(robot);
  std::size_t n = 1;  // the start cell is where the robot is
  for (; n < path.size(); ++n) {
    const plan::Pose2& p = path[n].pose;
    if (std::hypot(p.x - robot.x, p.y - robot.y) > range) break;
    if (!seen(map, rc, {path[n].cell.x, path[n].cell.y})) break;
  }
  return n;
}

std::size_t build_legs(std::span<const plan::Waypoint> prefix, double heading, int slices, std::span<Leg> out,
                       std::size_t& used) {
  std::size_t count = 0;
  used = prefix.empty() ? 0 : 1;
  if (prefix.size() < 2 || out.empty()) return 0;
  double h = heading;       // the robot's heading after the legs so far (unwrapped)
  int pending = 0;          // slices turned since the last translation (+ counter-clockwise)
  int last_dx = 0, last_dy = 0;
  for (std::size_t i = 1; i < prefix.size(); ++i) {
    const plan::CellPose& a = prefix[i - 1].cell;
    const plan::CellPose& b = prefix[i].cell;
    const int dx = b.x - a.x, dy = b.y - a.y;
    if (dx == 0 && dy == 0) {  // a turn in place by one slice
      if (slices > 1) pending += ((b.slice - a.slice + slices) % slices) == 1 ? 1 : -1;
      continue;
    }
    const bool same = count > 0 && pending == 0 && dx == last_dx && dy == last_dy;
    if (same) {
      out[count - 1].end = {prefix[i].pose.x, prefix[i].pose.y};
      used = i + 1;
      continue;
    }
    if (count == out.size()) break;
    const double d = std::atan2(static_cast<double>(dy), static_cast<double>(dx));
    Leg leg;
    leg.first = static_cast<std::uint32_t>(i - 1);
    leg.end = {prefix[i].pose.x, prefix[i].pose.y};
    if (slices > 0) {
      // Rectangle: the turns sweep the slices the path checked; then face d or d + π.
      const double turned = h + pending * 2.0 * plan::kPi / slices;
      const double fwd = nearest_turn(d, turned), back = nearest_turn(d + plan::kPi, turned);
      leg.forward = std::abs(fwd - turned) <= std::abs(back - turned);
      leg.heading = leg.forward ? fwd : back;
    } else {
      leg.heading = nearest_turn(d, h);  // disc: always forward, the shortest turn
    }
    h = leg.heading;
    pending = 0;
    last_dx = dx;
    last_dy = dy;
    out[count++] = leg;
    used = i + 1;
  }
  return count;
}

bool prefix_blocked(const plan::Planner& planner, std::span<const plan::Waypoint> prefix, std::size_t from) {
  for (std::size_t i = from; i < prefix.size(); ++i) {
    const plan::CellPose& w = prefix[i].cell;
    const plan::Cell c{w.x, w.y};
    if (planner.expanded(w.slice).at(c) == plan::kBlocked) return true;
    if (i > from) {
      const plan::CellPose& v = prefix[i - 1].cell;
      if (v.x == w.x && v.y == w.y && v.slice != w.slice &&
          (!planner.can_turn(c, v.slice) || !planner.can_turn(c, w.slice)))
        return true;
    }
  }
  return false;
}

double chain_length(std::span<const plan::Waypoint> path) {
  double len = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i)
    len += std::hypot(path[i].pose.x - path[i - 1].pose.x, path[i].pose.y - path[i - 1].pose.y);
  return len;
}

}  // namespace robuter::planner
