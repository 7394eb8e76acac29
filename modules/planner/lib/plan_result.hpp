// SPDX-License-Identifier: GPL-3.0-or-later
// Outcome of a plan: status, cost, geometric length and effort.
#pragma once

#include <cstdint>
#include <string_view>

namespace robuter::plan {

// How a plan ended. Only Found carries a path.
enum class PlanStatus : std::uint8_t {
  Found,         // a path from start to goal
  Unreachable,   // search exhausted: no path
  StartOutside,  // start is not on the map
  GoalOutside,   // goal is not on the map
  StartBlocked,  // start is an (expanded) obstacle
  GoalBlocked,   // goal is an (expanded) obstacle
  SearchLimit,   // the search needed more states than its memory budget holds (no path)
};

// Why: tools and logs print statuses by name.
constexpr std::string_view to_string(PlanStatus s) {
  switch (s) {
    case PlanStatus::Found: return "found";
    case PlanStatus::Unreachable: return "unreachable";
    case PlanStatus::StartOutside: return "start outside the map";
    case PlanStatus::GoalOutside: return "goal outside the map";
    case PlanStatus::StartBlocked: return "start blocked";
    case PlanStatus::GoalBlocked: return "goal blocked";
    case PlanStatus::SearchLimit: return "search memory exhausted";
  }
  return "?";
}

// Summary of one search.
struct PlanResult {
  PlanStatus status = PlanStatus::Unreachable;  // outcome
  double cost = 0.0;           // cells: path cost including unknown-cell multipliers and turns
  double length = 0.0;         // cells: geometric length (orthogonal 1, diagonal sqrt 2)
  std::uint32_t expanded = 0;  // nodes taken from the open list (effort)

  bool found() const { return status == PlanStatus::Found; }
};

}  // namespace robuter::plan
