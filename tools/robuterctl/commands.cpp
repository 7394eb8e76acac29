// SPDX-License-Identifier: GPL-3.0-or-later
// The command table of robuterctl (docs/PROTOCOL.md is the reference; this is its summary).
#include "tools/robuterctl/commands.hpp"

#include <fmt/format.h>

#include <array>

namespace robuter::ctl {

namespace {
constexpr std::array<CommandHelp, 59> kTable{{
    {"BO", "BO", "S <x> <y> <theta> <servo> <clock>", "posture: x, y in 0.1 mm, theta in 0.01 deg"},
    {"BU", "BU", "U <u1>…<u24> <servo> <clock>", "the 24 ultrasonic ranges, mm (0 = inactive or no echo yet)"},
    {"BV", "BV", "V <x> <y> <theta> <servo> <u1>…<u24> <clock>", "posture and ranges"},
    {"BC", "BC", "C <clock>", "internal clock, ticks of 10 ms"},
    {"BT", "BT", "T <ms>", "ultrasonic time-out"},
    {"BP", "BP", "P <p1>…<p72> <clock>", "pan-tilt sonar ranges, 72 sectors of 5 deg"},
    {"BF", "BF", "F <f1>…<f72> <clock>", "pan-tilt ranges after the spike filter"},
    {"BD", "BD", "D <d1>…<d72> <clock>", "differences of adjacent filtered pan-tilt ranges"},
    {"AM", "AM <left> <right>", "ack | error", "wheel speeds, cm/s (refused while an emergency holds)"},
    {"ASN", "ASN", "ack | error", "servo (brake) on"},
    {"ASF", "ASF", "ack | error", "servo (brake) off"},
    {"AY", "AY<command>", "ack | error", "pass a line to the low-level controller (when enabled)"},
    {"AC", "AC <x> <y> <theta>", "ack | error", "set the odometry posture (0.1 mm, 0.01 deg)"},
    {"AW", "AW <x> <y> <theta>", "ack | error", "go to that posture"},
    {"AX", "AX", "ack", "shut robuterd down (motors stopped, servo off)"},
    {"Ap", "Ap", "ack | error", "pan-tilt scanning on (error 16 no-unit without a unit)"},
    {"Ag", "Ag", "ack", "pan-tilt scanning off"},
    {"AG", "AG", "ack | error", "passage (gate) finder on"},
    {"AT", "AT", "ack", "passage finder off"},
    {"Ad", "Ad", "ack | error", "door-crossing mode on"},
    {"Af", "Af", "ack", "door-crossing mode off"},
    {"UT", "UT<24 × 0/1>", "ack | error", "active ultrasonic sensors, sensor 1 first"},
    {"UD", "UD<ticks>", "ack | error", "node firing delay"},
    {"UN", "UN", "N <ticks>", "node firing delay"},
    {"USN", "USN", "S <ticks>", "mean time to read one node"},
    {"USS", "USS", "S <ticks>", "mean time to read all six nodes"},
    {"Ut", "Ut<ms>", "ack | error", "ultrasonic time-out, 1…1000 ms"},
    {"Uu0", "Uu0", "ack", "auto-toggle of useless sensors off"},
    {"Uu1", "Uu1", "ack", "auto-toggle of useless sensors on"},
    {"XE", "XE", "E <held> <latched> <cause> <enabled> <clock> <granted> <rule> <protective>", "emergency state and its cause"},
    {"XR", "XR", "ack | error", "re-enable after a latched emergency (refused while its cause is present)"},
    {"XK", "XK", "K <ticks> <max-late-us> <p99-late-us> <n> {name act ovr slip mean max}×n <clock>", "kernel statistics"},
    {"XD", "XD", "D <pantilt> <reason> <gate> <reason> <doors> <reason> <sweeps> <width> <cross> <demo> <reason> <phase> <laps> <clock>",
     "pan-tilt, passage finder, door crossing and demonstration states"},
    {"XT1", "XT1", "ack | error", "start the demonstration course"},
    {"XT0", "XT0", "ack | error", "stop the demonstration course"},
    {"XV", "XV", "V robuterd <version> proto <n> caps <list>", "version and capabilities"},
    {"XS", "XS<ticks>", "ack | error", "status stream every <ticks> × 10 ms (10…60000), XS0 off"},
    {"XB0", "XB0", "ack", "bare `error` replies (default)"},
    {"XB1", "XB1", "ack", "verbose errors: `error <code> <reason>`"},
    {"XC0", "XC0", "ack", "line checksums off (robuterctl adds the checksum it needs)"},
    {"XC1", "XC1", "ack", "line checksums on: robuterctl appends *HHHH and checks replies"},
    {"XL0", "XL0", "ack", "replies end with CR (default)"},
    {"XL1", "XL1", "ack", "replies end with LF"},
    {"XL2", "XL2", "ack", "replies end with CR LF"},
    {"XG", "XG <x> <y> [<theta>]", "ack | error", "grid planner: navigate to a goal (0.1 mm, 0.01 deg)"},
    {"XH", "XH", "ack", "halt the grid planner"},
    {"XP", "XP", "P <state> <goal-x> <goal-y> <path-mm> <prefix-mm> <replans> <scans> <plan-us> <max-us> <clock>",
     "grid planner status"},
    {"XM", "XM", "M <w> <h> <cell-mm> <x> <y> <row1>|…|<rowh>", "the planner's map around the robot, drawn"},
    {"XN", "XN", "N <count> <number> <name>", "the place the robot is in (place graph; 0 - outside every place)"},
    {"XI", "XI <n>", "I <n> <name> <centre-x> <centre-y> <k> <neighbour>…", "place n of the place graph: centre (0.1 mm), neighbours by door"},
    {"XQ", "XQ <n>", "ack | error", "go to place n over the place graph's route (the grid planner drives it; XP follows, XH stops)"},
    {"XW", "XW", "W <state> <x> <y> <theta> <major-mm> <minor-mm> <axis> <sigma-theta> <cluster-%> <particles> <steps> <clock>",
     "where the robot is on its map: the localisation's estimate and its uncertainty"},
    {"XA", "XA [<x> <y> <theta>]", "ack | error", "the robot's pose on its map (0.1 mm, 0.01 deg); XA alone: a global search"},
    {"help", "help [command]", "", "this list, or one command's syntax and reply", true},
    {"stop", "stop", "", "send the stop byte 0x18 now (as Ctrl-X): the robot stops and latches; XR re-enables", true},
    {"status", "status", "", "the latest status-stream line, decoded", true},
    {"quit", "quit", "", "leave robuterctl (as Ctrl-D)", true},
    {"exit", "exit", "", "leave robuterctl (as Ctrl-D)", true},
    {"clear", "clear", "", "clear the screen", true},
}};
}  // namespace

std::span<const CommandHelp> command_table() { return kTable; }

std::string help_text(std::string_view word) {
  std::string out;
  if (word.empty()) {
    out += "Commands (Tab completes; `help CMD` for one). Ctrl-X sends the stop byte at any moment.\n";
    for (const auto& c : kTable) out += fmt::format("  {:<22} {}{}\n", c.syntax, c.summary, c.local ? " (local)" : "");
    out += "Keys: Ctrl-X stop byte · Ctrl-C cancel the line · Ctrl-D quit · Up/Down history\n";
    return out;
  }
  for (const auto& c : kTable) {
    if (c.name.substr(0, word.size()) != word && !(word.size() > c.name.size() && word.substr(0, c.name.size()) == c.name))
      continue;
    out += fmt::format("  {}\n      {}{}\n", c.syntax, c.summary, c.local ? " (robuterctl, not sent)" : "");
    if (!c.reply.empty()) out += fmt::format("      reply: {}\n", c.reply);
  }
  if (out.empty()) out = fmt::format("no command '{}' (help lists them)\n", word);
  return out;
}

}  // namespace robuter::ctl
