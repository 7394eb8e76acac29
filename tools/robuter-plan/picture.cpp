// SPDX-License-Identifier: GPL-3.0-or-later
// The tool's picture of a plan: the planner copied into a snapshot, drawn by the module's picture code.
#include "tools/robuter-plan/picture.hpp"

#include <cmath>

#include "modules/planner/lib/plan_snapshot.hpp"
#include "modules/planner/picture/plan_picture.hpp"

namespace robuter::plan::tool {

Status write_picture(const Planner& planner, const Pose2& start, Point2 goal, const std::string& path,
                     const PlanResult* result) {
  PlanSnapshot snap;
  snap.reserve(planner, planner.waypoints().size());
  PlanResult shown;
  shown.status = planner.waypoints().empty() ? PlanStatus::Unreachable : PlanStatus::Found;
  if (result != nullptr) shown = *result;
  if (!snap.capture(planner, shown, start, goal)) return Error{path, 0, "the planner has no map"};
  snap.length = 0.0;
  for (std::size_t i = 1; i < snap.path_len; ++i)
    snap.length += std::hypot(snap.path[i].pose.x - snap.path[i - 1].pose.x, snap.path[i].pose.y - snap.path[i - 1].pose.y);
  snap.plan_number = 1;
  PlanPictureOptions options;
  options.what = "robuter-plan";  // its maps (thesis files, worlds) are in the world frame
  auto laid = write_plan_picture(snap, path, options);
  if (!laid) return laid.error();
  return Ok{};
}

}  // namespace robuter::plan::tool
