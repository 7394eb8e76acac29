// SPDX-License-Identifier: GPL-3.0-or-later
// The planner's picture thread: take a snapshot from the mailbox, draw it, free the slot.
#include "modules/planner/picture_writer.hpp"

#include <cstdio>

#include "modules/planner/picture/plan_picture.hpp"

namespace robuter::planner {

bool PictureWriter::drain() {
  const plan::PlanSnapshot* snap = box_.take();
  if (snap == nullptr) return false;
  char name[64];
  std::snprintf(name, sizeof name, "/plan-g%03u-%03u.png", snap->goal_seq, snap->plan_number);
  plan::PlanPictureOptions options;
  const std::optional<plan::Pose2> frame = map_in_world_ ? map_in_world_() : std::nullopt;
  options.world_frame = frame.has_value();
  options.map_in_world = frame.value_or(plan::Pose2{});
  char what[64];
  std::snprintf(what, sizeof what, "robuterd plan %03u for XG goal %03u", snap->plan_number, snap->goal_seq);
  options.what = what;
  const auto st = plan::write_plan_picture(*snap, dir_ + name, options);
  box_.release();
  if (!st) {
    // Not the kernel's thread: a message on stderr costs the robot nothing.
    if (failed_.fetch_add(1) == 0) std::fprintf(stderr, "robuterd: planner picture: %s\n", st.error().text().c_str());
    return false;
  }
  written_.fetch_add(1);
  return true;
}

}  // namespace robuter::planner
