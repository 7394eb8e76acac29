// Handler of XD: the pan-tilt scanner's, passage finder's, door crossing's and demonstration's states.
#include "protocol/codec/handlers.hpp"

namespace robuter::protocol {

// XD → `D <pantilt> <reason> <gate> <reason> <doors> <reason> <sweeps> <width-mm> <cross-ticks>
// <demo> <reason> <phase> <laps> <clock>`: states, reasons and the phase are single words from
// the port (the demonstration's words come after the older fields, so readers of those keep working).
// XT1 / XT0: the demonstration course started (taking the robot) or stopped.
void handle_set_demo(const Command& cmd, RobotPort& port, ReplyWriter& out) noexcept {
  reply_result(port.set_demo(cmd.choice == '1'), out);
}

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
  out.word(r.demo.state);
  out.word(r.demo.reason);
  out.word(r.demo_phase);
  out.field(r.demo_laps);
  out.field(port.clock());
}

}  // namespace robuter::protocol
