// SPDX-License-Identifier: GPL-3.0-or-later
// The command link's client sessions against the order of a client's open and first bytes: a
// scripted stream makes the client arrive between the link's look at the events and its read.
#include <gtest/gtest.h>

#include <array>
#include <deque>
#include <string>

#include "kernel/clock.hpp"
#include "kernel/config.hpp"
#include "kernel/kernel.hpp"
#include "modules/serial/serial_module.hpp"
#include "modules/topics.hpp"

namespace robuter {
namespace {

// A pty-like stream whose client opens it and writes its first line the moment the link has
// looked at the client events and found none: what a loaded machine did to links.pty_clients on
// CI (the session started one activation after the client's first lines were answered).
class LateClientStream final : public hal::ByteStream {
 public:
  explicit LateClientStream(std::string first) : first_(std::move(first)) {}
  const char* name() const override { return "scripted pty"; }
  int fd() const override { return -1; }
  hal::IoResult read(std::span<std::uint8_t> out) override {
    std::size_t n = 0;
    while (n < out.size() && !input_.empty()) {
      out[n++] = static_cast<std::uint8_t>(input_.front());
      input_.pop_front();
    }
    return {n, false};
  }
  hal::IoResult write(std::span<const std::uint8_t> in) override {
    output_.append(in.begin(), in.end());
    return {in.size(), false};
  }
  bool reopen() override { return true; }
  bool connected() const override { return true; }
  hal::ClientEvent next_client_event() override {
    if (!events_.empty()) {
      const auto e = events_.front();
      events_.pop_front();
      return e;
    }
    if (!arrived_) {  // the client opens (the event is queued), then writes
      arrived_ = true;
      events_.push_back(hal::ClientEvent::session_start);
      write_line(first_);
    }
    return hal::ClientEvent::none;
  }
  bool client_present() const override { return arrived_; }

  void write_line(const std::string& line) { input_.insert(input_.end(), line.begin(), line.end()), input_.push_back('\r'); }
  // The reply lines written so far, each without its CR; taken.
  std::string take_output() { return std::exchange(output_, {}); }

 private:
  std::string first_;
  bool arrived_ = false;
  std::deque<hal::ClientEvent> events_;
  std::deque<char> input_;
  std::string output_;
};

struct OneLink {
  explicit OneLink(const std::string& first) : stream(first), kernel(clock, 10'000'000) {
    rows[0] = ProcessRow{"serial", &link, 1, 0, 0, 2000};
    ok = !kernel.set_table(rows) && kernel.start();
  }
  ~OneLink() { kernel.shutdown(); }
  void step(int n) {
    for (int i = 0; i < n; ++i) {
      clock.advance(10'000'000);
      kernel.step();
    }
  }

  LateClientStream stream;
  std::array<hal::ByteStream*, 1> streams{&stream};
  LinkSettings settings;
  Blackboard bb;
  VirtualClock clock;
  Kernel kernel;
  SerialModule link{bb, settings, streams};
  std::array<ProcessRow, 1> rows{};
  bool ok = false;
};

// The client's first line is a session setting (XB1: numbered errors): it holds for the lines
// after it, and the session counted once. Before the link looked at the events after each
// read, the late-seen start reset the session and the next error was the seed's bare `error`.
TEST(LinkSessions, AClientsFirstLineIsServedInItsOwnSessionWhenItsOpenIsSeenLate) {
  OneLink rig("XB1");
  ASSERT_TRUE(rig.ok);
  rig.step(3);
  EXPECT_EQ(rig.stream.take_output(), "ack\r");
  EXPECT_EQ(rig.bb.link_status.reader().peek().sessions, 1u);
  rig.stream.write_line("Zz");
  rig.step(2);
  EXPECT_EQ(rig.stream.take_output(), "error 1 unknown-command\r");
  EXPECT_EQ(rig.bb.link_status.reader().peek().sessions, 1u);
}

}  // namespace
}  // namespace robuter
