// SPDX-License-Identifier: GPL-3.0-or-later
// Handlers of the B messages: posture, ranges, clock, time-out and pan-tilt arrays.
#include "protocol/codec/handlers.hpp"
#include "protocol/codec/posture_fields.hpp"

namespace robuter::protocol {
namespace {

// `<letter> <p1> … <p72> <clock>` for one pan-tilt array, or `error` when there is none.
void reply_sectors(char letter, SectorKind kind, RobotPort& port, ReplyWriter& out) noexcept {
  Sectors sectors{};
  if (refused(port.pan_tilt(kind, sectors), out)) return;
  const char head[2] = {letter, '\0'};
  out.open(std::string_view(head, 1));
  out.fields(sectors);
  out.field(port.clock());
}

}  // namespace

// BO → `S <x> <y> <theta> <servo> <clock>`.
void handle_get_posture(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  out.open("S");
  posture_fields(port, out);
  out.field(port.clock());
}

// BU → `U <u1> … <u24> <servo> <clock>`.
void handle_get_ranges(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  Ranges ranges{};
  port.ranges(ranges);
  out.open("U");
  out.fields(ranges);
  out.field(port.servo_on() ? 1 : 0);
  out.field(port.clock());
}

// BV → `V <x> <y> <theta> <servo> <u1> … <u24> <clock>` (the seed code's order).
void handle_get_posture_ranges(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  Ranges ranges{};
  port.ranges(ranges);
  out.open("V");
  posture_fields(port, out);
  out.fields(ranges);
  out.field(port.clock());
}

// BC → `C <clock>`.
void handle_get_clock(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  out.open("C");
  out.field(port.clock());
}

// BT → `T <timeout>` in ms.
void handle_get_us_timeout(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  out.open("T");
  out.field(port.us_timeout());
}

// BP → `P <p1> … <p72> <clock>`.
void handle_get_pan_tilt_raw(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  reply_sectors('P', SectorKind::raw, port, out);
}

// BF → `F <f1> … <f72> <clock>`.
void handle_get_pan_tilt_filtered(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  reply_sectors('F', SectorKind::filtered, port, out);
}

// BD → `D <d1> … <d72> <clock>`.
void handle_get_pan_tilt_differences(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  reply_sectors('D', SectorKind::differences, port, out);
}

}  // namespace robuter::protocol
