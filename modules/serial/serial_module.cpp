// Link service: attach and re-attach clients, feed bytes to the codec, queue and flush replies.
#include "modules/serial/serial_module.hpp"

#include "kernel/kernel.hpp"
#include "kernel/log.hpp"

namespace robuter {

SerialModule::SerialModule(Blackboard& bb, const Config& cfg, std::span<hal::ByteStream* const> links)
    : writers_{bb.link_motion.writer(), bb.servo_request.writer(), bb.odometry_set.writer(), bb.go_to.writer(),
               bb.us_settings.writer(), bb.link_status.writer(),  bb.modes.writer(),
               bb.planner_goal.writer(), bb.operator_events.writer()},
      port_(bb, writers_, cfg) {
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
    l.in_len = l.in_pos = 0;
  }
  if (l.watched_fd < 0 && k.watch_fd(s.fd(), this)) l.watched_fd = s.fd();

  flush(l);
  for (;;) {
    // Read more only when everything read before has been answered.
    if (l.in_pos == l.in_len) {
      const hal::IoResult r = s.read(l.in);
      if (r.closed) {
        note_closed(l);
        k.unwatch_fd(l.watched_fd);
        l.watched_fd = -1;
        return;
      }
      if (r.bytes == 0) break;
      l.in_len = r.bytes;
      l.in_pos = 0;
    }
    // Feed one byte at a time while a whole reply still fits: replies are never dropped, and
    // a client that does not read only stalls its own link.
    while (l.in_pos < l.in_len && l.out.free() >= protocol::kReplyCapacity) {
      l.codec.feed(std::span<const std::uint8_t>(&l.in[l.in_pos], 1), port_,
                   [&](std::string_view reply) { l.out.push(reply); });
      ++l.in_pos;
    }
    flush(l);
    if (l.in_pos < l.in_len) break;  // output full: wait for the client to read
  }
  if (const auto line = l.codec.poll_stream(port_); line && l.out.free() >= line->size()) l.out.push(*line);
  flush(l);
}

void SerialModule::run(Kernel& k) {
  std::uint32_t open = 0;
  for (std::size_t i = 0; i < link_count_; ++i) {
    serve(k, links_[i]);
    if (links_[i].stream->connected()) ++open;
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
  }
}

}  // namespace robuter
