// SPDX-License-Identifier: GPL-3.0-or-later
// robuter-can-nodes' script: ranges, silence, faults and bus errors, one command per line.
#include "tools/robuter-can-nodes/node_commands.hpp"

#include <fcntl.h>
#include <linux/can/error.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>

#include "kernel/split_words.hpp"

namespace robuter::tools {

namespace {
bool number(std::string_view s, unsigned& v, int base = 10) {
  if (base == 16 && s.rfind("0x", 0) == 0) s.remove_prefix(2);
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v, base);
  return r.ec == std::errc{} && r.ptr == s.data() + s.size();
}

bool flag(std::string_view s, bool& on) {
  if (s == "1" || s == "on") on = true;
  else if (s == "0" || s == "off") on = false;
  else return false;
  return true;
}
}  // namespace

NodeCommands::NodeCommands(int fd, ScriptedNodes nodes, std::FILE* out) : fd_(fd), n_(std::move(nodes)), out_(out) {
  const int fl = ::fcntl(fd_, F_GETFL);
  if (fl >= 0) ::fcntl(fd_, F_SETFL, fl | O_NONBLOCK);
}

bool NodeCommands::poll(std::int64_t now_us) {
  char buf[256];
  while (open_ && !quit_) {
    const ssize_t r = ::read(fd_, buf, sizeof buf);
    if (r > 0) {
      pending_.append(buf, static_cast<std::size_t>(r));
      for (std::size_t nl; (nl = pending_.find('\n')) != std::string::npos;) {
        apply(std::string_view(pending_).substr(0, nl), now_us);
        pending_.erase(0, nl + 1);
      }
      if (pending_.size() > 1024) pending_.clear();  // no line is that long: drop it
    } else if (r == 0) {
      open_ = false;  // end of input: the nodes go on as they are
    } else {
      break;  // EAGAIN (nothing yet) or an error: try again next step
    }
  }
  return !quit_;
}

void NodeCommands::apply(std::string_view line, std::int64_t now_us) {
  const auto w = split_words(line, " \t\r");  // a CRLF script's '\r' separates too
  if (w.empty() || w[0].front() == '#') return;
  auto reply = [&](const char* what) {
    std::fprintf(out_, "robuter-can-nodes: %.*s: %s\n", static_cast<int>(line.size()), line.data(), what);
    std::fflush(out_);
  };
  auto drives = [&](std::string_view who) {
    std::vector<hal::can::SimDriveNode*> d;
    if (who == "left" || who == "drives") d.push_back(n_.left);
    if (who == "right" || who == "drives") d.push_back(n_.right);
    return d;
  };
  unsigned a = 0, b = 0;
  bool on = false;
  if (w[0] == "range" && w.size() == 2 && number(w[1], a) && a <= 65535) {  // range MM: every transducer
    for (auto* s : n_.sonars)
      for (int i = 0; i < 4; ++i) s->set_range(i, static_cast<std::uint16_t>(a));
    return reply("ok");
  }
  if (w[0] == "range" && w.size() == 3 && number(w[1], a) && number(w[2], b) && a >= 1 &&
      a <= 4 * n_.sonars.size() && b <= 65535) {  // range S MM: transducer S (node (S-1)/4, input (S-1)%4)
    n_.sonars[(a - 1) / 4]->set_range(static_cast<int>((a - 1) % 4), static_cast<std::uint16_t>(b));
    return reply("ok");
  }
  if (w[0] == "silent" && w.size() == 3 && flag(w[2], on)) {  // silent left|right|drives|sonar 0|1
    if (w[1] == "sonar") {
      for (auto* s : n_.sonars) s->set_silent(on);
      return reply("ok");
    }
    const auto d = drives(w[1]);
    if (d.empty()) return reply("error: silent left|right|drives|sonar 0|1");
    for (auto* x : d) x->set_silent(on);
    return reply("ok");
  }
  if (w[0] == "fault" && w.size() == 3 && number(w[2], a, 16) && a > 0 && a <= 0xFFFF) {  // fault left|right CODE
    const auto d = drives(w[1]);
    if (d.empty()) return reply("error: fault left|right|drives CODE");
    for (auto* x : d) x->inject_fault(static_cast<std::uint16_t>(a));
    return reply("ok");
  }
  if (w[0] == "reboot" && w.size() == 2) {  // reboot left|right|drives: a power cycle
    const auto d = drives(w[1]);
    if (d.empty()) return reply("error: reboot left|right|drives");
    for (auto* x : d) x->reboot(now_us);
    return reply("ok");
  }
  if ((w[0] == "busoff" || w[0] == "restarted") && w.size() == 1) {  // an error frame to robuterd
    can_frame f{};
    f.can_id = CAN_ERR_FLAG | (w[0] == "busoff" ? CAN_ERR_BUSOFF : CAN_ERR_RESTARTED);
    f.len = CAN_ERR_DLC;
    if (n_.wire == nullptr || !n_.wire->send(f)) return reply("error: the error frame was not sent");
    return reply("ok");
  }
  if (w[0] == "quit" && w.size() == 1) {
    quit_ = true;
    return reply("ok");
  }
  reply("error: range [S] MM | silent left|right|drives|sonar 0|1 | fault left|right|drives HEX | "
        "reboot left|right|drives | busoff | restarted | quit");
}

}  // namespace robuter::tools
