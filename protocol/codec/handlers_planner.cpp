// SPDX-License-Identifier: GPL-3.0-or-later
// Handlers of the grid planner's X extensions: goal, halt, status and the map window.
#include "protocol/codec/handlers.hpp"

namespace robuter::protocol {

// XG <x> <y> [<theta>]: the port refuses a goal off the map (out_of_range) or while latched.
void handle_set_goal(const Command& cmd, RobotPort& port, ReplyWriter& out) noexcept {
  const bool with_theta = cmd.int_count == 3;
  reply_result(port.set_goal(Posture{cmd.ints[0], cmd.ints[1], with_theta ? cmd.ints[2] : 0}, with_theta), out);
}

// XH: stop navigating (ack even when idle).
void handle_cancel_goal(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  reply_result(port.cancel_goal(), out);
}

// XP → `P <state> <goal-x> <goal-y> <path-mm> <prefix-mm> <replans> <scans> <plan-us>
// <max-us> <clock>`.
void handle_get_planner_status(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  PlannerReport r;
  if (refused(port.planner_status(r), out)) return;
  out.open("P");
  out.word(word(r.state));
  out.fields({r.goal_x, r.goal_y, r.path_mm, r.prefix_mm, r.replans, r.scans, r.plan_us, r.max_us, port.clock()});
}

// XM → `M <w> <h> <cell-mm> <x> <y> <row1>|<row2>|…|<rowh>`: rows top first, one character a
// cell, exactly one space before the first row (rows may begin and end with spaces: free cells).
void handle_get_planner_map(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  MapWindow w;
  if (refused(port.planner_map(w), out)) return;
  const auto side = static_cast<std::size_t>(w.side > 0 ? w.side : 0);
  if (side == 0 || w.cells.size() != side * side) {
    out.error(ErrorCode::unavailable);
    return;
  }
  out.open("M");
  out.fields({w.side, w.side, w.cell_mm, w.center_x, w.center_y});
  out.raw(" ");
  for (std::size_t row = 0; row < side; ++row) {
    if (row > 0) out.raw("|");
    out.raw(w.cells.substr(row * side, side));
  }
}

}  // namespace robuter::protocol
