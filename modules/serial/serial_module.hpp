// SPDX-License-Identifier: GPL-3.0-or-later
// The command-link process: reads every link, answers each complete line in order, never blocks.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "hal/api/byte_stream.hpp"
#include "kernel/process.hpp"
#include "modules/serial/link_port.hpp"
#include "modules/serial/link_settings.hpp"
#include "modules/serial/output_ring.hpp"
#include "modules/topics.hpp"
#include "protocol/codec/link_codec.hpp"

namespace robuter {

class SerialModule final : public Process {
 public:
  static constexpr std::size_t kMaxLinks = 4;           // links served at once
  static constexpr std::size_t kOutputBytes = 64 * 1024;  // replies queued per link, bytes
  static constexpr std::size_t kReadChunk = 512;        // bytes read per read() call
  static constexpr std::size_t kMaxReadsPerRun = 256;   // read() calls per link per activation (128 kB: more
                                                        // than a pty or a serial driver buffers)
  static constexpr std::size_t kBacklogBytes = 16 * 1024;  // bytes read and scanned but not yet handled per
                                                           // link: lines waiting for a command's owner to run

  // `links` must outlive the module; at most kMaxLinks are used. `settings` is copied.
  SerialModule(Blackboard& bb, const LinkSettings& settings, std::span<hal::ByteStream* const> links);
  // The port holds references to this module's writers and settings: neither copied nor moved.
  SerialModule(const SerialModule&) = delete;
  SerialModule& operator=(const SerialModule&) = delete;
  // The emergency module, woken in the same tick by a stop byte or a motion request.
  void set_emergency(Process* p) { port_.set_emergency(p); }
  // The executor, run before the next line after a servo or odometry request (read-your-writes).
  void set_executor(Process* p) { port_.set_executor(p); }
  // The localisation, run before the next line after AC or XA.
  void set_localise(Process* p) { port_.set_localise(p); }
  void set_places(const places::PlaceGraph* graph, const places::RouteTable* routes) {  // XN, XI, XQ
    port_.set_places(graph, routes);
  }
  bool init(Kernel& k) override;
  void run(Kernel& k) override;
  void close(Kernel& k) override;

 private:
  struct Link {
    hal::ByteStream* stream = nullptr;          // transport
    protocol::LinkCodec codec;                  // framing, session, replies
    OutputRing<kOutputBytes> out;               // replies not yet written
    std::array<std::uint8_t, kReadChunk> in{};  // bytes of the last read
    int watched_fd = -1;                        // descriptor that wakes the kernel, -1 none
    int watched_event_fd = -1;                  // the stream's client-event descriptor, watched, -1 none
    bool lost_device = false;                   // the device went away (not a client leaving)
    std::uint64_t discarded = 0;                // lines dropped unexecuted since the client stopped reading
    std::array<std::uint8_t, kBacklogBytes> backlog{};  // bytes read, not yet handled: [head, tail)
    std::size_t head = 0;
    std::size_t tail = 0;
    std::size_t stops = 0;                      // stop bytes in the backlog
  };

  // Serves one link: attach/detach, client sessions, flush, read, answer, flush.
  void serve(Kernel& k, Link& l);
  // Reads every byte waiting (bounded) and feeds it; with `sessions`, each read's bytes after the
  // client events that came before them. False when the stream closed.
  bool pump(Kernel& k, Link& l, bool sessions);
  // Client sessions in the order they happened, with `bytes` just read in hand: a session that
  // ended takes them (and what else its client wrote) before it ends. False when the stream closed.
  bool client_events(Kernel& k, Link& l, std::span<const std::uint8_t>& bytes);
  // Feeds bytes in order: lines are executed while a whole reply still fits the output ring, and
  // dropped unexecuted (counted) when it does not; the stop byte acts in both cases. Unless
  // `all`, stops before a line that must wait for the owners of an earlier command (a stop byte
  // further on lifts the wait up to it). Returns how many bytes were fed.
  std::size_t feed(Link& l, std::span<const std::uint8_t> bytes, bool all);
  // Appends bytes read to the link's backlog (its stop bytes counted) and handles what can be.
  void take(Link& l, std::span<const std::uint8_t> bytes);
  // Handles the backlog as far as it can now; `all`: to the end, without waiting.
  void handle(Link& l, bool all);
  // Drops the backlog (a new session, a device back).
  static void clear_backlog(Link& l) { l.head = l.tail = l.stops = 0; }
  // A new client session: previous replies, half line and settings are dropped.
  void start_session(Link& l);
  // The last client left: its unsent replies go; the robot stops if so configured.
  void end_session(Link& l);
  // Logs and counts a link that closed (device lost or client gone).
  void note_closed(Link& l);
  // Writes queued replies as far as the transport takes them.
  void flush(Link& l);

  LinkSettings settings_;     // what the link checks commands against (the port holds a reference)
  LinkWriters writers_;       // topics this module owns, lent to the port
  LinkPort port_;             // the protocol's view of the robot
  std::array<Link, kMaxLinks> links_{};
  std::size_t link_count_ = 0;
  std::size_t first_link_ = 0;            // the link served first, rotated every activation
  bool stop_when_clients_leave_ = false;  // [links] stop_when_clients_leave
};

}  // namespace robuter
