// SPDX-License-Identifier: GPL-3.0-or-later
// The per-line path: checksum check (when on), decode, run the handler. (The communication
// watchdog is stamped by the codec for every complete line, before this.)
#include "protocol/codec/line_handler.hpp"

#include "protocol/codec/checksum.hpp"
#include "protocol/codec/decoder.hpp"

namespace robuter::protocol {

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
