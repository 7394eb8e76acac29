// SPDX-License-Identifier: GPL-3.0-or-later
// The codec of one link: framing, session state and replies bundled for the serial module.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "protocol/codec/line_assembler.hpp"
#include "protocol/codec/line_handler.hpp"
#include "protocol/codec/reply_writer.hpp"
#include "protocol/codec/robot_port.hpp"
#include "protocol/codec/session.hpp"

namespace robuter::protocol {

// Owned by whoever owns the link, one per client. Not copyable (the writers point at the
// session). Feed it the bytes read; it calls the port and hands each reply line to a sink.
class LinkCodec {
 public:
  LinkCodec() noexcept = default;
  LinkCodec(const LinkCodec&) = delete;
  LinkCodec& operator=(const LinkCodec&) = delete;

  // For every event in `bytes`: a line → its reply to `sink(std::string_view)`; a framing
  // error → `error` to the sink; the stop byte → port.immediate_stop() and nothing written.
  // Every complete line, valid or not, first stamps the communication watchdog
  // (port.message_received(), as the seed's serial.c did).
  // Each reply view is valid until the sink returns; write it out (or copy it) there.
  template <class Sink>
  void feed(std::span<const std::uint8_t> bytes, RobotPort& port, Sink&& sink) {
    assembler_.feed(bytes, [&](const FrameEvent& event) {
      switch (event.kind) {
        case FrameEvent::Kind::line:
          port.message_received();
          sink(handle_line(event.line, port, writer_));
          break;
        case FrameEvent::Kind::error:
          port.message_received();
          sink(reply_error(event.error, writer_));
          break;
        case FrameEvent::Kind::stop: port.immediate_stop(); break;
        case FrameEvent::Kind::none: break;
      }
    });
  }

  // Frames `bytes` without executing anything: the stop byte still calls
  // port.immediate_stop(); every line (or framing error) completed is dropped unanswered (it
  // still stamps the watchdog: the client is there). Returns how many were dropped. For a link
  // whose replies cannot be queued (docs/PROTOCOL.md: a client that does not read).
  std::size_t discard(std::span<const std::uint8_t> bytes, RobotPort& port) {
    std::size_t dropped = 0;
    assembler_.feed(bytes, [&](const FrameEvent& event) {
      if (event.kind == FrameEvent::Kind::stop) {
        port.immediate_stop();
      } else if (event.kind != FrameEvent::Kind::none) {
        port.message_received();
        ++dropped;
      }
    });
    return dropped;
  }

  // The status line due at `port.clock()` when streaming is on, else nothing. The first line
  // comes at once after XS, then one every stream_period ticks.
  std::optional<std::string_view> poll_stream(const RobotPort& port) noexcept;

  // The link's options (the serial module may preset the terminator from its configuration).
  SessionState& session() noexcept { return session_; }
  const SessionState& session() const noexcept { return session_; }
  // Drops a partial line and returns the session to seed behaviour (link reopened).
  void reset() noexcept;
  // True when byte `b`, fed next, would complete a line (its reply or error).
  bool ends_line(std::uint8_t b) const noexcept { return assembler_.ends_line(b); }

 private:
  SessionState session_{};               // options switched on by the client
  LineAssembler assembler_{};            // bytes → lines
  ReplyWriter writer_{session_};         // replies to lines
  ReplyWriter stream_writer_{session_};  // stream lines (separate, never clobbers a reply)
  std::uint32_t streamed_period_ = 0;    // stream_period when the last line was sent
  Ticks last_stream_ = 0;                // clock of the last stream line
};

}  // namespace robuter::protocol
