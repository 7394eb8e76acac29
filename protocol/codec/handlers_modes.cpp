// Handler of XD: the pan-tilt scanner's, passage finder's and door crossing's states.
#include "protocol/codec/handlers.hpp"

namespace robuter::protocol {

// XD → `D <pantilt> <reason> <gate> <reason> <doors> <reason> <sweeps> <width-mm> <cross-ticks>
// <clock>`: states and reasons are single words from the port.
void handle_get_modes(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  ModesReport r;
  const PortResult res = port.modes(r);
  if (res != PortResult::ok) {
    out.error(error_for(res));
    return;
  }
  out.open("D");
  for (const ModeWords* m : {&r.pan_tilt, &r.gate, &r.doors}) {
    out.word(m->state);
    out.word(m->reason);
  }
  out.field(r.sweeps);
  out.field(r.width_mm);
  out.field(r.crossing_ticks);
  out.field(port.clock());
}

}  // namespace robuter::protocol
