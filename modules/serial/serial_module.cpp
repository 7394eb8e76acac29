// SPDX-License-Identifier: GPL-3.0-or-later
// Link service: attach and re-attach clients, feed bytes to the codec, queue and flush replies.
#include "modules/serial/serial_module.hpp"

#include <algorithm>
#include <cstring>

#include "kernel/kernel.hpp"
#include "kernel/log.hpp"

namespace robuter {

SerialModule::SerialModule(Blackboard& bb, const LinkSettings& settings, std::span<hal::ByteStream* const> links)
    : settings_(settings),
      writers_{bb.link_motion.writer(), bb.servo_request.writer(), bb.odometry_set.writer(), bb.go_to.writer(),
               bb.us_settings.writer(), bb.link_status.writer(),  bb.modes.writer(),
               bb.planner_goal.writer(), bb.operator_events.writer(), bb.localise_request.writer()},
      port_(bb, writers_, settings_),
      stop_when_clients_leave_(settings.stop_when_clients_leave) {
  for (hal::ByteStream* s : links) {
    if (link_count_ == kMaxLinks) break;
    links_[link_count_++].stream = s;
  }
  // The ring's settings start as the configuration says.
  writers_.us.publish(settings.initial_us);
}

bool SerialModule::init(Kernel& k) {
  port_.attach(k);
  for (std::size_t i = 0; i < link_count_; ++i) log::info("serial: serving {}", links_[i].stream->name());
  return true;
}

void SerialModule::flush(Link& l) {
  while (l.out.size() > 0) {
    const auto chunk = l.out.front();
    const hal::IoResult r = l.stream->write(chunk);
    if (r.closed || r.bytes == 0) return;
    l.out.pop(r.bytes);
  }
}

// A device that went away is logged with its reason and counted (LinkStatus), apart from a
// client that merely left its pty.
void SerialModule::note_closed(Link& l) {
  const hal::ByteStream& s = *l.stream;
  const char* why = s.loss_reason();
  if (why == nullptr) {
    log::info("serial: client left {}", s.name());
    return;
  }
  log::warn("serial: {} lost ({}); looking for it again", s.name(), why);
  writers_.status.modify([](LinkStatus& st) { ++st.devices_lost; });
  l.lost_device = true;
}

void SerialModule::start_session(Link& l) {
  clear_backlog(l);
  l.codec.reset();
  l.out.clear();
  l.stream->discard_unread_output();
  l.discarded = 0;
  writers_.status.modify([](LinkStatus& st) { ++st.sessions; });
  log::info("serial: client attached on {}", l.stream->name());
}

// What the leaving client wrote is handled first, without waiting: nobody reads its replies.
void SerialModule::end_session(Link& l) {
  handle(l, true);
  clear_backlog(l);
  l.codec.reset();
  l.out.clear();
  l.stream->discard_unread_output();
  if (stop_when_clients_leave_) {
    log::info("serial: last client left {}: stopping the robot ([links] stop_when_clients_leave)", l.stream->name());
    port_.immediate_stop();
  } else {
    log::info("serial: client left {}", l.stream->name());
  }
}

std::size_t SerialModule::feed(Link& l, std::span<const std::uint8_t> bytes, bool all) {
  std::uint64_t dropped = 0;
  std::size_t i = 0;
  for (; i < bytes.size(); ++i) {
    const std::uint8_t b = bytes[i];
    // Read-your-writes: the next line waits until the owners of the last command have run; a
    // line on a link silent past the communication limit waits for the emergency module to see
    // it alive. A stop byte further on is not kept waiting: what comes before it is handled now.
    if (!all && l.stops == 0 && (port_.waiting() || (l.codec.ends_line(b) && port_.revive_link()))) break;
    if (b == protocol::kStopByte) --l.stops;
    const auto one = bytes.subspan(i, 1);
    if (l.out.free() >= protocol::kReplyCapacity) {
      l.codec.feed(one, port_, [&](std::string_view reply) { l.out.push(reply); });
    } else {
      dropped += l.codec.discard(one, port_);
    }
  }
  if (dropped == 0) {
    if (l.discarded > 0 && l.out.free() >= protocol::kReplyCapacity) {
      log::info("serial: {} reads its replies again ({} lines were dropped unexecuted)", l.stream->name(), l.discarded);
      l.discarded = 0;
    }
    return i;
  }
  if (l.discarded == 0)
    log::warn("serial: {}: client does not read its replies ({} bytes queued): lines dropped unexecuted",
              l.stream->name(), l.out.size());
  l.discarded += dropped;
  writers_.status.modify([&](LinkStatus& st) { st.lines_discarded += dropped; });
  return i;
}

void SerialModule::handle(Link& l, bool all) {
  if (l.head == l.tail) return;
  l.head += feed(l, std::span<const std::uint8_t>(l.backlog.data() + l.head, l.tail - l.head), all);
  if (l.head == l.tail) l.head = l.tail = 0;
}

// The backlog is bounded: when bytes read do not fit behind lines still waiting, those lines
// are handled now, without waiting (a client that pipelines more than kBacklogBytes behind
// commands gets its replies in order, but not each query after the command before it).
void SerialModule::take(Link& l, std::span<const std::uint8_t> bytes) {
  if (l.backlog.size() - l.tail < bytes.size() && l.head > 0) {
    std::memmove(l.backlog.data(), l.backlog.data() + l.head, l.tail - l.head);
    l.tail -= l.head;
    l.head = 0;
  }
  if (l.backlog.size() - l.tail < bytes.size()) handle(l, true);
  std::copy(bytes.begin(), bytes.end(), l.backlog.begin() + static_cast<std::ptrdiff_t>(l.tail));
  l.tail += bytes.size();
  l.stops += static_cast<std::size_t>(std::count(bytes.begin(), bytes.end(), protocol::kStopByte));
  handle(l, false);
}

// The client events are looked at after each read, before its bytes are taken: a client opens
// the pty before it writes, so the start of its session is always seen before its first line.
// (Looked at before the read, a client could open and write between the two: its first lines
// would be answered, and then its session started, dropping their settings and replies.)
bool SerialModule::pump(Kernel& k, Link& l, bool sessions) {
  for (std::size_t reads = 0; reads < kMaxReadsPerRun; ++reads) {
    const hal::IoResult r = l.stream->read(l.in);
    if (r.closed) {
      note_closed(l);
      k.unwatch_fd(l.watched_fd);
      l.watched_fd = -1;
      return false;
    }
    std::span<const std::uint8_t> bytes(l.in.data(), r.bytes);
    if (sessions && !client_events(k, l, bytes)) return false;
    if (!bytes.empty()) {
      take(l, bytes);
      flush(l);
    }
    if (r.bytes == 0) break;
  }
  return true;
}

bool SerialModule::client_events(Kernel& k, Link& l, std::span<const std::uint8_t>& bytes) {
  for (hal::ClientEvent e = l.stream->next_client_event(); e != hal::ClientEvent::none;
       e = l.stream->next_client_event()) {
    if (e == hal::ClientEvent::session_start) {
      start_session(l);
    } else if (e == hal::ClientEvent::shared) {
      // Not refused (a terminal and a logger may share a link on purpose), but said: replies
      // go to whichever program reads first.
      log::warn("serial: a second program opened {} while a client holds it: both read its replies", l.stream->name());
    } else {
      // What the leaving client wrote, the bytes in hand and the rest, is served in its own
      // session before the session ends.
      if (!bytes.empty()) take(l, bytes);
      bytes = {};
      if (!pump(k, l, false)) return false;
      end_session(l);
    }
  }
  return true;
}

// Every readable byte is read and scanned: the stop byte acts whatever the output's state, and
// a line whose reply cannot be queued is dropped, never left waiting to run unseen later.
void SerialModule::serve(Kernel& k, Link& l) {
  hal::ByteStream& s = *l.stream;
  if (!s.connected()) {
    if (l.watched_fd >= 0) {  // closed while writing
      note_closed(l);
      k.unwatch_fd(l.watched_fd);
      l.watched_fd = -1;
    }
    // Lines read before the end (standard input's EOF) still wait for their owners, in order;
    // their replies go out where the transport still writes (standard output).
    if (l.head != l.tail) {
      handle(l, false);
      flush(l);
      if (l.head != l.tail) return;
    }
    if (!s.reopen()) return;  // cheap for a pty; a serial device is looked for off this path
    if (l.lost_device) {
      log::info("serial: {} is back", s.name());
      writers_.status.modify([](LinkStatus& st) { ++st.devices_back; });
      l.lost_device = false;
    } else {
      log::info("serial: client attached on {}", s.name());
    }
    clear_backlog(l);
    l.codec.reset();
    l.out.clear();
  }
  if (l.watched_fd < 0 && k.watch_fd(s.fd(), this)) l.watched_fd = s.fd();
  if (l.watched_event_fd < 0 && s.event_fd() >= 0 && k.watch_fd(s.event_fd(), this)) l.watched_event_fd = s.event_fd();

  flush(l);
  handle(l, false);  // lines that waited for an owner, before the bytes read now
  flush(l);
  if (!pump(k, l, true)) return;
  if (const auto line = l.codec.poll_stream(port_); line && l.out.free() >= line->size()) l.out.push(*line);
  flush(l);
}

// Links take turns at being served first, so one that pipelines commands (each waiting for
// its owner) cannot keep the others' lines waiting for long.
void SerialModule::run(Kernel& k) {
  std::uint32_t open = 0;
  bool backlog = false;
  for (std::size_t n = 0; n < link_count_; ++n) {
    Link& l = links_[(first_link_ + n) % link_count_];
    serve(k, l);
    if (l.stream->client_present()) ++open;
    backlog = backlog || l.head != l.tail;
  }
  if (link_count_ > 0) first_link_ = (first_link_ + 1) % link_count_;
  // Lines wait for the owners of a command: run again once they have (they are triggered and
  // run first, by priority), within the kernel's bound on triggered runs; else at the next
  // period or bytes.
  if (backlog) k.trigger(this);
  if (open != writers_.status.current().links_open) writers_.status.modify([&](LinkStatus& s) { s.links_open = open; });
  if (port_.shutdown_requested()) {
    for (std::size_t i = 0; i < link_count_; ++i) flush(links_[i]);  // the `ack` goes out first
    log::info("serial: AX received, shutting down");
    k.request_stop();
  }
}

void SerialModule::close(Kernel& k) {
  for (std::size_t i = 0; i < link_count_; ++i) {
    flush(links_[i]);
    if (links_[i].watched_fd >= 0) k.unwatch_fd(links_[i].watched_fd);
    if (links_[i].watched_event_fd >= 0) k.unwatch_fd(links_[i].watched_event_fd);
  }
}

}  // namespace robuter
