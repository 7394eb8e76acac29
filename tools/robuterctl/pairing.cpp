// SPDX-License-Identifier: GPL-3.0-or-later
// Protocol pairing of replies (see pairing.hpp).
#include "tools/robuterctl/pairing.hpp"

#include <cstdlib>
#include <vector>

#include "kernel/split_words.hpp"
#include "protocol/codec/checksum.hpp"

namespace robuter::ctl {

namespace {

// The command word of a line as sent: its first two characters.
std::string_view head(std::string_view line) {
  while (!line.empty() && (line.front() == ' ' || line.front() == ',')) line.remove_prefix(1);
  return line.substr(0, 2);
}

bool starts(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

}  // namespace

std::string with_checksum(std::string_view line) {
  char hex[protocol::kChecksumDigits];
  protocol::format_checksum(protocol::crc16(line), hex);
  std::string out(line);
  out += protocol::kChecksumMark;
  out.append(hex, protocol::kChecksumDigits);
  return out;
}

bool reply_fits(std::string_view sent, std::string_view reply) {
  if (reply == "error" || starts(reply, "error ")) return true;  // any line can be refused
  const auto w = split_words(reply, " ");  // a reply's words are separated by spaces
  if (w.empty()) return false;
  const std::string_view h = head(sent);
  const std::string_view r = w[0];
  const std::size_t n = w.size();
  if (h.size() < 2) return false;
  if (reply == "ack")
    return h[0] == 'A' || h == "UT" || h == "UD" || h == "Ut" || h == "Uu" || h == "XR" || h == "XT" || h == "XS" ||
           h == "XB" || h == "XC" || h == "XL" || h == "XG" || h == "XH";
  if (h == "BO") return r == "S" && n == 6;
  if (h == "BU") return r == "U" && n == 27;
  if (h == "BV") return r == "V" && n == 30;
  if (h == "BC") return r == "C" && n == 2;
  if (h == "BT") return r == "T" && n == 2;
  if (h == "BP") return r == "P" && n == 74;
  if (h == "BF") return r == "F" && n == 74;
  if (h == "BD") return r == "D" && n == 74;
  if (h == "UN") return r == "N" && n == 2;
  if (h == "US") return r == "S" && n == 2;
  if (h == "XE") return r == "E" && n >= 6;
  if (h == "XK") return r == "K" && n >= 5;
  if (h == "XD") return r == "D" && n >= 11 && n != 74;
  if (h == "XV") return r == "V" && n >= 2 && w[1] == "robuterd";
  if (h == "XP") return r == "P" && n >= 10 && n != 74;
  if (h == "XM") return r == "M" && n >= 6;
  return false;
}

std::string Pairing::outgoing(std::string_view line, bool internal) {
  waiting_.push_back(Waiting{std::string(line), internal, Clock::now(), false});
  std::string out = checksums_ ? with_checksum(line) : std::string(line);
  out += '\r';
  return out;
}

Incoming Pairing::incoming(std::string_view line) {
  Incoming in;
  std::string_view body = line;
  if (line.size() > protocol::kChecksumDigits && line[line.size() - protocol::kChecksumDigits - 1] == protocol::kChecksumMark) {
    std::string_view stripped;
    if (protocol::strip_checksum(line, stripped)) body = stripped;
    else if (checksums_) in.checksum_bad = true;
  } else if (checksums_) {
    in.checksum_bad = true;
  }
  in.text = std::string(body);
  if (!body.empty() && body.front() == '@') {
    in.kind = Incoming::Kind::stream;
    return in;
  }
  // The oldest waiting line this can answer; the ones before it got no reply.
  for (std::size_t i = 0; i < waiting_.size(); ++i) {
    if (!reply_fits(waiting_[i].command, body)) continue;
    in.kind = Incoming::Kind::reply;
    in.command = waiting_[i].command;
    in.internal = waiting_[i].internal;
    in.lost = i;
    waiting_.erase(waiting_.begin(), waiting_.begin() + static_cast<std::ptrdiff_t>(i) + 1);
    follow(in.command, body);
    return in;
  }
  in.kind = Incoming::Kind::unexpected;
  return in;
}

void Pairing::follow(const std::string& command, std::string_view reply) {
  if (reply != "ack") return;
  std::string_view c = command;
  while (!c.empty() && c.front() == ' ') c.remove_prefix(1);
  while (!c.empty() && c.back() == ' ') c.remove_suffix(1);
  if (c == "XC1") checksums_ = true;
  else if (c == "XC0") checksums_ = false;
  else if (c == "XB1") verbose_ = true;
  else if (c == "XB0") verbose_ = false;
  else if (c == "XL0") terminator_ = 0;
  else if (c == "XL1") terminator_ = 1;
  else if (c == "XL2") terminator_ = 2;
  else if (starts(c, "XS")) stream_period_ = std::atoi(std::string(c.substr(2)).c_str());
}

}  // namespace robuter::ctl
