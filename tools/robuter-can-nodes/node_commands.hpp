// SPDX-License-Identifier: GPL-3.0-or-later
// robuter-can-nodes' script: lines on standard input that set the ranges and inject faults.
#pragma once

#include <array>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "hal/linux/can/frame_transport.hpp"
#include "hal/linux/can/sim_nodes.hpp"

namespace robuter::tools {

// What the script acts on: the two drives, the ultrasonic nodes (4 transducers each) and the wire
// (robuterd's side of the bus, for error frames).
struct ScriptedNodes {
  hal::can::SimDriveNode* left = nullptr;
  hal::can::SimDriveNode* right = nullptr;
  std::vector<hal::can::SimSonarNode*> sonars;  // node 0 first
  hal::can::FrameTransport* wire = nullptr;
};

// Reads whole lines from a descriptor without blocking (O_NONBLOCK is set on it) and applies each
// (docs/CAN.md, "robuter-can-nodes' script"). A bad line is reported on `out` and changes nothing.
class NodeCommands {
 public:
  NodeCommands(int fd, ScriptedNodes nodes, std::FILE* out);
  // Applies every complete line read so far; false once the input ended or said `quit`.
  bool poll(std::int64_t now_us);
  // Applies one line (the script's grammar); the reply printed on `out`.
  void apply(std::string_view line, std::int64_t now_us);

 private:
  int fd_;
  ScriptedNodes n_;
  std::FILE* out_;
  std::string pending_;  // bytes read after the last newline
  bool open_ = true;
  bool quit_ = false;
};

}  // namespace robuter::tools
