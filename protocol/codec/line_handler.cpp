// The per-line path: checksum check (when on), decode, stamp the watchdog, run the handler.
#include "protocol/codec/line_handler.hpp"

#include "protocol/codec/checksum.hpp"
#include "protocol/codec/decoder.hpp"

namespace robuter::protocol {

// Only lines that decode to a command count as a message for the communication watchdog, so
// noise on a dead link does not keep the robot believing its client is alive.
std::string_view handle_line(std::string_view line, RobotPort& port, ReplyWriter& out) noexcept {
  out.begin();
  std::string_view body = line;
  if (out.session().checksums && !strip_checksum(line, body)) {
    out.error(ErrorCode::bad_checksum);
    return out.finish();
  }
  const Decoded d = decode(body);
  if (d.error != ErrorCode::none) {
    out.error(d.error);
    return out.finish();
  }
  port.message_received();
  d.row->handler(d.command, port, out);
  return out.finish();
}

// Framing errors take the same path out as decoding errors.
std::string_view reply_error(ErrorCode code, ReplyWriter& out) noexcept {
  out.begin();
  out.error(code);
  return out.finish();
}

}  // namespace robuter::protocol
