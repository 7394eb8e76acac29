// SPDX-License-Identifier: GPL-3.0-or-later
// Handler of XD: the pan-tilt scanner's, passage finder's, door crossing's and demonstration's states.
#include "protocol/codec/handlers.hpp"

namespace robuter::protocol {

namespace {
// A mode's state and reason words; a mode whose module is not running reads "absent none".
void mode_words(const ModeReport& m, ReplyWriter& out) noexcept {
  out.word(m.absent ? kAbsentWord : word(m.state));
  out.word(word(m.absent ? ModeReason::none : m.reason));
}
}  // namespace

// XT1 / XT0: the demonstration course started (taking the robot) or stopped.
void handle_set_demo(const Command& cmd, RobotPort& port, ReplyWriter& out) noexcept {
  reply_result(port.set_demo(cmd.choice == '1'), out);
}

// XD → `D <pantilt> <reason> <gate> <reason> <doors> <reason> <sweeps> <width-mm> <cross-ticks>
// <demo> <reason> <phase> <laps> <clock>`: states, reasons and the phase are single words of the
// vocabulary (the demonstration's words come after the older fields, so readers of those keep working).
void handle_get_modes(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  ModesReport r;
  if (refused(port.modes(r), out)) return;
  out.open("D");
  for (const ModeReport* m : {&r.pan_tilt, &r.gate, &r.doors}) mode_words(*m, out);
  out.fields({r.sweeps, r.width_mm, r.crossing_ticks});
  mode_words(r.demo, out);
  out.word(r.demo.absent || r.demo.state == ModeState::off ? kNoPhaseWord : word(r.demo_phase));
  out.fields({r.demo_laps, port.clock()});
}

}  // namespace robuter::protocol
