// SPDX-License-Identifier: GPL-3.0-or-later
// Handlers of the localisation's X extensions: the pose on the map (XW) and setting it (XA).
#include "protocol/codec/handlers.hpp"

namespace robuter::protocol {

// XW → `W <state> <x> <y> <theta> <major-mm> <minor-mm> <axis> <sigma-theta> <cluster-%>
// <particles> <steps> <clock>`.
void handle_get_localisation(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  LocaliseReport r;
  if (refused(port.localisation(r), out)) return;
  out.open("W");
  out.word(word(r.state));
  out.fields({r.x, r.y, r.theta, r.major_mm, r.minor_mm, r.axis, r.sigma_theta, r.cluster_pct, r.particles,
              r.steps, port.clock()});
}

// XA <x> <y> <theta>: the robot is there on its map; XA alone: a global search.
void handle_set_map_pose(const Command& cmd, RobotPort& port, ReplyWriter& out) noexcept {
  const bool global = cmd.int_count == 0;
  reply_result(port.set_map_pose(global ? Posture{} : Posture{cmd.ints[0], cmd.ints[1], cmd.ints[2]}, global), out);
}

}  // namespace robuter::protocol
