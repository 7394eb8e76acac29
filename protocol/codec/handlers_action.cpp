// SPDX-License-Identifier: GPL-3.0-or-later
// Handlers of the A messages (motion, servo, pass-through, odometry, go-to, shutdown); a port's answer as ack or error.
#include "protocol/codec/handlers.hpp"

namespace robuter::protocol {

// Each refusal keeps its reason so verbose errors can tell them apart.
ErrorCode error_for(PortResult result) noexcept {
  switch (result) {
    case PortResult::ok: return ErrorCode::none;
    case PortResult::refused_emergency: return ErrorCode::refused_emergency;
    case PortResult::not_permitted: return ErrorCode::not_permitted;
    case PortResult::out_of_range: return ErrorCode::out_of_range;
    case PortResult::unavailable: return ErrorCode::unavailable;
    case PortResult::busy: return ErrorCode::busy;
    case PortResult::no_unit: return ErrorCode::no_unit;
  }
  return ErrorCode::internal;
}

// The one place a refusal becomes the reply, for commands and reports alike.
bool refused(PortResult result, ReplyWriter& out) noexcept {
  if (result == PortResult::ok) return false;
  out.error(error_for(result));
  return true;
}

// The common ending of every A/U command: `ack` or the refusal.
void reply_result(PortResult result, ReplyWriter& out) noexcept {
  if (!refused(result, out)) out.ack();
}

// AM <left> <right>: a request to move, which the emergency module may refuse.
void handle_move(const Command& cmd, RobotPort& port, ReplyWriter& out) noexcept {
  reply_result(port.request_motion(cmd.ints[0], cmd.ints[1]), out);
}

// ASN switches the servo on, ASF off (the seed code's reading).
void handle_servo(const Command& cmd, RobotPort& port, ReplyWriter& out) noexcept {
  reply_result(port.set_servo(cmd.choice == 'N'), out);
}

// AY<line>: the port applies the configuration's allow-list.
void handle_pass_through(const Command& cmd, RobotPort& port, ReplyWriter& out) noexcept {
  reply_result(port.pass_through(cmd.text), out);
}

// AC <x> <y> <theta>: re-seed odometry.
void handle_set_odometry(const Command& cmd, RobotPort& port, ReplyWriter& out) noexcept {
  reply_result(port.set_odometry(Posture{cmd.ints[0], cmd.ints[1], cmd.ints[2]}), out);
}

// AW <x> <y> <theta>: start moving to a posture.
void handle_go_to(const Command& cmd, RobotPort& port, ReplyWriter& out) noexcept {
  reply_result(port.go_to(Posture{cmd.ints[0], cmd.ints[1], cmd.ints[2]}), out);
}

// AX: the port raises the shutdown request; the link writes the ack before closing.
void handle_shutdown(const Command&, RobotPort& port, ReplyWriter& out) noexcept {
  reply_result(port.request_shutdown(), out);
}

}  // namespace robuter::protocol
