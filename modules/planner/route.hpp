// SPDX-License-Identifier: GPL-3.0-or-later
// From a planned path to what the robot executes: the visible prefix (seed 000) and its legs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "modules/planner/lib/geometry.hpp"
#include "modules/planner/lib/occupancy_map.hpp"
#include "modules/planner/lib/planner.hpp"

namespace robuter::planner {

// One straight piece of the followed path: turn in place to `heading`, then drive to `end`.
struct Leg {
  plan::Point2 end;           // m, where the leg ends (a cell centre)
  double heading = 0.0;       // rad, unwrapped: continuous with the robot's heading at the plan
  bool forward = true;        // drive facing `heading` (true) or backing along it (false)
  bool drive = true;          // false: a turn in place only (final heading at the goal)
  std::uint32_t first = 0;    // index in the prefix of the waypoint the leg starts from
};

// Why: seed 000 hands the controller only the part of the path the sonar can vouch for: the
// waypoints from the start on that are within `range` (m) of `robot` and seen from it (the
// straight line between the two cells crosses no obstacle cell; unknown counts as free, as the
// thesis assumes). Returns how many leading waypoints qualify (at least 1 for a non-empty path).
std::size_t visible_prefix(const plan::OccupancyMap& map, std::span<const plan::Waypoint> path, plan::Point2 robot,
                           double range);

// Why: a path is cells with heading slices; the robot executes "turn in place, drive straight".
// Consecutive moves along one direction make one leg; turns between slices (rectangle) pick the
// heading to face: the move's direction or its opposite, whichever the path's turns lead to
// (`heading` = the robot's unwrapped heading at the start, `slices` = the planner's full-turn
// slices (2K), 0 for a disc, which
// always drives forward). Writes at most out.size() legs and returns how many; `used` = how
// many waypoints those legs cover (fewer than the prefix when `out` is full).
std::size_t build_legs(std::span<const plan::Waypoint> prefix, double heading, int slices, std::span<Leg> out,
                       std::size_t& used);

// Why: a new obstacle on the part still to drive, or where a turn is to happen, means stop and
// replan. Checks waypoints [from, prefix.size()) against the planner's layers (sync() first).
bool prefix_blocked(const plan::Planner& planner, std::span<const plan::Waypoint> prefix, std::size_t from);

// Why: XP reports lengths; the length of a waypoint chain, m.
double chain_length(std::span<const plan::Waypoint> path);

}  // namespace robuter::planner
