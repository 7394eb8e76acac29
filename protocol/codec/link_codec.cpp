// SPDX-License-Identifier: GPL-3.0-or-later
// The non-template parts of the link codec: the stream schedule and reset.
#include "protocol/codec/link_codec.hpp"

#include "protocol/codec/stream_encoder.hpp"

namespace robuter::protocol {

// A changed period restarts the schedule so a client sees the first line right away.
std::optional<std::string_view> LinkCodec::poll_stream(const RobotPort& port) noexcept {
  const std::uint32_t period = session_.stream_period;
  if (period == 0) {
    streamed_period_ = 0;
    return std::nullopt;
  }
  const Ticks now = port.clock();
  if (period == streamed_period_ && now - last_stream_ < static_cast<Ticks>(period)) {
    return std::nullopt;
  }
  streamed_period_ = period;
  last_stream_ = now;
  return encode_status_line(port, stream_writer_);
}

// A new client starts from the seed's behaviour.
void LinkCodec::reset() noexcept {
  assembler_.reset();
  session_ = SessionState{};
  streamed_period_ = 0;
  last_stream_ = 0;
}

}  // namespace robuter::protocol
