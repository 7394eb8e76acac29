// SPDX-License-Identifier: GPL-3.0-or-later
// Replies decoded for people: names and units for each field of the seed's and extension replies.
#pragma once

#include <string>

namespace robuter::ctl {

// The fields of `reply` named and in units, given the command `sent` that it answers (pairing.hpp
// makes sure it does); empty when there is nothing to add to the reply as it stands (`ack`).
std::string describe_reply(const std::string& sent, const std::string& reply);

// The state an `XE` reply or a status-stream line reports.
struct EmergencyView {
  bool valid = false;    // the line was an XE reply / stream line
  bool latched = false;
  bool held = false;
  std::string cause;     // XE only (the stream carries no cause)
  bool protective = false;  // a protective stop is in force (XE's 9th field, the stream's +4)
};
EmergencyView read_xe(const std::string& xe_reply);
EmergencyView read_stream(const std::string& at_line);
// The live line shown when a protective stop begins (an obstacle in the envelope; no XR needed).
std::string protective_banner();

// The banner for a latched emergency and its cause.
std::string emergency_banner(const std::string& cause);

// A status-stream line (`@ x y theta servo left right emergency clock`) in words.
std::string describe_stream(const std::string& at_line);

}  // namespace robuter::ctl
