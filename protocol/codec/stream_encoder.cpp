// SPDX-License-Identifier: GPL-3.0-or-later
// Encoder of the status stream's lines: a compact snapshot that never looks like a reply.
#include "protocol/codec/stream_encoder.hpp"

#include "protocol/codec/posture_fields.hpp"

namespace robuter::protocol {

// Three bits so a client sees "waiting for data", "stopped by an emergency" and "stopped short
// of an obstacle" (a protective stop, which needs no XR) apart.
int stream_emergency_field(const EmergencyStatus& status) noexcept {
  return (status.held ? 1 : 0) + (status.latched ? 2 : 0) + (status.protective ? 4 : 0);
}

// '@' starts no reply, so an opted-in client can tell stream lines from replies.
std::string_view encode_status_line(const RobotPort& port, ReplyWriter& out) noexcept {
  out.begin();
  const WheelSpeeds w = port.wheel_speeds();
  out.open("@");
  posture_fields(port, out);
  out.fields({w.left, w.right, stream_emergency_field(port.emergency()), port.clock()});
  return out.finish();
}

}  // namespace robuter::protocol
