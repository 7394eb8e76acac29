// SPDX-License-Identifier: GPL-3.0-or-later
// Handlers of the localisation's X extensions: the pose on the map (XW) and setting it (XA).
#include "protocol/codec/handlers.hpp"

namespace robuter::protocol {

// XW → `W <state> <x> <y> <theta> <major-mm> <minor-mm> <axis> <sigma-theta> <cluster-%>
// <particles> <steps> <clock>`.
void handle_get_localisation(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  LocaliseReport r;
  const PortResult res = port.localisation(r);
  if (res != PortResult::ok) {
    out.error(error_for(res));
    return;
  }
  out.open("W");
  out.raw(" ");
  out.raw(word(r.state));
  out.field(r.x);
  out.field(r.y);
  out.field(r.theta);
  out.field(r.major_mm);
  out.field(r.minor_mm);
  out.field(r.axis);
  out.field(r.sigma_theta);
  out.field(r.cluster_pct);
  out.field(r.particles);
  out.field(r.steps);
  out.field(port.clock());
}

// XA <x> <y> <theta>: the robot is there on its map; XA alone: a global search.
void handle_set_map_pose(const Command& cmd, RobotPort& port, ReplyWriter& out) noexcept {
  const bool global = cmd.int_count == 0;
  reply_result(port.set_map_pose(global ? Posture{} : Posture{cmd.ints[0], cmd.ints[1], cmd.ints[2]}, global), out);
}

}  // namespace robuter::protocol
