// Link service: attach and re-attach clients, feed bytes to the codec, queue and flush replies.
#include "modules/serial/serial_module.hpp"

#include "kernel/kernel.hpp"
#include "kernel/log.hpp"

namespace robuter {

SerialModule::SerialModule(Blackboard& bb, const Config& cfg, std::span<hal::ByteStream* const> links)
    : writers_{bb.link_motion.writer(), bb.servo_request.writer(), bb.odometry_set.writer(), bb.go_to.writer(),
               bb.us_settings.writer(), bb.link_status.writer(),  bb.modes.writer(),
               bb.planner_goal.writer(), bb.operator_events.writer()},
      port_(bb, writers_, cfg),
      stop_when_clients_leave_(cfg.links.stop_when_clients_leave) {
  for (hal::ByteStream* s : links) {
    if (link_count_ == kMaxLinks) break;
    links_[link_count_++].stream = s;
  }
  // The ring's settings start as the configuration says.
  writers_.us.publish(UltrasonicSettings{0xFFFFFF, cfg.sonar.node_delay_ticks, cfg.sonar.timeout_ms,
                                         cfg.emergency.auto_toggle});
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
  l.codec.reset();
  l.out.clear();
  l.stream->discard_unread_output();
  l.discarded = 0;
  writers_.status.modify([](LinkStatus& st) { ++st.sessions; });
  log::info("serial: client attached on {}", l.stream->name());
}

void SerialModule::end_session(Link& l) {
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

void SerialModule::feed(Link& l, std::span<const std::uint8_t> bytes) {
  std::uint64_t dropped = 0;
  for (std::size_t i = 0; i < bytes.size(); ++i) {
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
    return;
  }
  if (l.discarded == 0)
    log::warn("serial: {}: client does not read its replies ({} bytes queued): lines dropped unexecuted",
              l.stream->name(), l.out.size());
  l.discarded += dropped;
  writers_.status.modify([&](LinkStatus& st) { st.lines_discarded += dropped; });
}

bool SerialModule::pump(Kernel& k, Link& l) {
  hal::ByteStream& s = *l.stream;
  for (std::size_t reads = 0; reads < kMaxReadsPerRun; ++reads) {
    const hal::IoResult r = s.read(l.in);
    if (r.closed) {
      note_closed(l);
      k.unwatch_fd(l.watched_fd);
      l.watched_fd = -1;
      return false;
    }
    if (r.bytes == 0) break;
    feed(l, std::span<const std::uint8_t>(l.in.data(), r.bytes));
    flush(l);
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
    if (!s.reopen()) return;  // cheap for a pty; a serial device is looked for off this path
    if (l.lost_device) {
      log::info("serial: {} is back", s.name());
      writers_.status.modify([](LinkStatus& st) { ++st.devices_back; });
      l.lost_device = false;
    } else {
      log::info("serial: client attached on {}", s.name());
    }
    l.codec.reset();
    l.out.clear();
  }
  if (l.watched_fd < 0 && k.watch_fd(s.fd(), this)) l.watched_fd = s.fd();
  if (l.watched_event_fd < 0 && s.event_fd() >= 0 && k.watch_fd(s.event_fd(), this)) l.watched_event_fd = s.event_fd();

  // Client sessions in the order they happened; what a leaving client wrote is served in its
  // own session before the session ends.
  for (hal::ClientEvent e = s.next_client_event(); e != hal::ClientEvent::none; e = s.next_client_event()) {
    if (e == hal::ClientEvent::session_start) {
      start_session(l);
    } else {
      if (!pump(k, l)) return;
      end_session(l);
    }
  }
  flush(l);
  if (!pump(k, l)) return;
  if (const auto line = l.codec.poll_stream(port_); line && l.out.free() >= line->size()) l.out.push(*line);
  flush(l);
}

void SerialModule::run(Kernel& k) {
  std::uint32_t open = 0;
  for (std::size_t i = 0; i < link_count_; ++i) {
    serve(k, links_[i]);
    if (links_[i].stream->client_present()) ++open;
  }
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
