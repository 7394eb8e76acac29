// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the whole link codec with the fake robot port, checking reply invariants.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string_view>

#include "protocol/codec/link_codec.hpp"
#include "protocol/testing/fake_robot_port.hpp"

using namespace robuter::protocol;

namespace {

// Counts the terminated lines the framing will see, to compare with the reply count.
struct TerminatorCounter {
  bool after_cr = false;  // last byte was CR (an LF next is not a terminator)
  std::size_t count = 0;  // terminators seen
  void push(std::uint8_t b) {
    if (b == kStopByte) return;
    if (b == '\n' && after_cr) {
      after_cr = false;
      return;
    }
    after_cr = b == '\r';
    if (b == '\r' || b == '\n') ++count;
  }
};

// Every reply: non-empty, printable body, ends with exactly the terminator, nothing inside.
void check_reply(std::string_view reply) {
  if (reply.empty() || reply.size() > kReplyCapacity) std::abort();
  const std::size_t end = reply.find_first_of("\r\n");
  if (end == std::string_view::npos || end == 0) std::abort();
  const std::string_view tail = reply.substr(end);
  if (tail != "\r" && tail != "\n" && tail != "\r\n") std::abort();
  for (char c : reply.substr(0, end)) {
    if (c < 0x20 || c > 0x7E) std::abort();
  }
}

}  // namespace

// The first byte picks the port's scripted answers; the rest is fed in two chunks so split
// lines are exercised; the stream is polled after every reply.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  testing::FakeRobotPort port;
  LinkCodec codec;
  if (size > 0) {
    port.result = static_cast<PortResult>(data[0] % 6);
    port.motion_result = static_cast<PortResult>((data[0] / 6) % 6);
    port.has_pan_tilt = (data[0] & 0x80) == 0;
    ++data;
    --size;
  }
  TerminatorCounter expected;
  for (std::size_t i = 0; i < size; ++i) expected.push(data[i]);
  std::size_t replies = 0;
  auto sink = [&](std::string_view reply) {
    check_reply(reply);
    ++replies;
    port.now += 3;
    if (auto s = codec.poll_stream(port)) check_reply(*s);
  };
  const std::size_t half = size / 2;
  codec.feed(std::span(data, half), port, sink);
  codec.feed(std::span(data + half, size - half), port, sink);
  if (replies != expected.count) std::abort();
  if (port.shutdowns > 0 && replies == 0) std::abort();
  return 0;
}
