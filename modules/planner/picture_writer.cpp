// SPDX-License-Identifier: GPL-3.0-or-later
// The planner's picture thread: draw the snapshot taken from the mailbox into its PNG.
#include "modules/planner/picture_writer.hpp"

#include <cstdio>

#include "modules/planner/picture/plan_picture.hpp"

namespace robuter::planner {

std::optional<std::string> PictureWriter::write(const plan::PlanSnapshot& snap) {
  char name[64];
  std::snprintf(name, sizeof name, "/plan-g%03u-%03u.png", snap.goal_seq, snap.plan_number);
  plan::PlanPictureOptions options;
  const std::optional<plan::Pose2> frame = map_in_world_ ? map_in_world_() : std::nullopt;
  options.world_frame = frame.has_value();
  options.map_in_world = frame.value_or(plan::Pose2{});
  char what[64];
  std::snprintf(what, sizeof what, "robuterd plan %03u for XG goal %03u", snap.plan_number, snap.goal_seq);
  options.what = what;
  const auto st = plan::write_plan_picture(snap, dir_ + name, options);
  if (!st) return st.error().text();
  return std::nullopt;
}

}  // namespace robuter::planner
