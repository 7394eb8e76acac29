// SPDX-License-Identifier: GPL-3.0-or-later
// The posture fields shared by BO, BV and the status stream: one order for all three.
#include "protocol/codec/posture_fields.hpp"

namespace robuter::protocol {

// The seed's order: the posture, then the servo.
void posture_fields(const RobotPort& port, ReplyWriter& out) noexcept {
  const Posture p = port.posture();
  out.fields({p.x, p.y, p.theta, port.servo_on() ? 1 : 0});
}

}  // namespace robuter::protocol
