// SPDX-License-Identifier: GPL-3.0-or-later
// Test harness: a LinkCodec and a fake port, fed with strings, collecting replies as strings.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "protocol/codec/link_codec.hpp"
#include "protocol/testing/fake_robot_port.hpp"

namespace robuter::protocol::testing {

// One client link under test.
struct Harness {
  FakeRobotPort port;                // the robot
  LinkCodec codec;                   // the link's codec
  std::vector<std::string> replies;  // every reply line so far, terminator included

  // Feeds raw bytes; returns the replies they produced.
  std::vector<std::string> feed(std::string_view bytes) {
    const std::size_t before = replies.size();
    codec.feed(std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), port,
               [this](std::string_view r) { replies.emplace_back(r); });
    return {replies.begin() + static_cast<std::ptrdiff_t>(before), replies.end()};
  }

  // Sends one line with CR; returns its single reply without the CR ("" if not exactly one).
  std::string ask(std::string_view line) {
    std::string bytes(line);
    bytes += '\r';
    const std::vector<std::string> got = feed(bytes);
    if (got.size() != 1 || got[0].empty() || got[0].back() != '\r') return "<bad reply count>";
    return got[0].substr(0, got[0].size() - 1);
  }
};

}  // namespace robuter::protocol::testing
