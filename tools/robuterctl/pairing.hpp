// SPDX-License-Identifier: GPL-3.0-or-later
// Replies paired with the lines that asked for them by the protocol, never by count.
//
// robuterd answers every line with exactly one reply, in order (docs/PROTOCOL.md §1), and never
// starts a reply with `@`, which marks status-stream lines (§8 `XS`). A console still meets lines
// that answer nothing it sent: a reply an earlier client left unread, the late reply to a line
// whose wait ran out. So a line is taken as the reply to the oldest line still waiting only when
// its shape is one that line's command can get (`BO` → `S` and five integers or `error`, `AM` →
// `ack` or `error`, ...); a line no waiting command can get is shown apart as unexpected. The
// session options that change what lines look like — checksums (`XC1`, §9) and the terminator
// (`XL`) — are followed from the replies that acknowledge them.
#pragma once

#include <chrono>
#include <cstddef>
#include <deque>
#include <string>
#include <string_view>

namespace robuter::ctl {

// True when `reply` (checksum removed) is a reply the command `sent` can get. Lines that are not a
// known command (`Zz`, too short) can only get `error`.
bool reply_fits(std::string_view sent, std::string_view reply);

// A line of the link, classified.
struct Incoming {
  enum class Kind {
    reply,       // the reply to `command`
    stream,      // a status-stream line (`@ …`)
    unexpected,  // answers nothing waiting: stale input, or a late reply
  };
  Kind kind = Kind::unexpected;
  std::string text;          // the line without its checksum
  std::string command;       // reply: the line it answers (as typed, without checksum)
  bool internal = false;     // reply: to a line the console sent on its own (not shown as typed)
  bool checksum_bad = false; // checksums are on and the line's is missing or wrong
  std::size_t lost = 0;      // reply: earlier waiting lines that got no reply (dropped by robuterd)
};

class Pairing {
 public:
  using Clock = std::chrono::steady_clock;
  struct Waiting {
    std::string command;     // as typed (no checksum)
    bool internal = false;
    Clock::time_point sent{};
    bool overdue_told = false;
  };

  // The bytes to write for `line` (its checksum when checksums are on, then CR), remembered as
  // waiting for its reply.
  std::string outgoing(std::string_view line, bool internal = false);
  // Classifies one received line (terminator removed) and follows the session options its reply
  // acknowledges.
  Incoming incoming(std::string_view line);

  bool checksums() const { return checksums_; }
  int terminator() const { return terminator_; }      // 0 CR, 1 LF, 2 CR LF (XL)
  int stream_period() const { return stream_period_; } // XS ticks, 0 = off
  bool verbose() const { return verbose_; }
  std::deque<Waiting>& waiting() { return waiting_; }
  const std::deque<Waiting>& waiting() const { return waiting_; }
  // A fresh session (a new client): every option off, nothing waiting.
  void reset() { *this = Pairing{}; }

 private:
  void follow(const std::string& command, std::string_view reply);
  std::deque<Waiting> waiting_;
  bool checksums_ = false;
  int terminator_ = 0;
  int stream_period_ = 0;
  bool verbose_ = false;
};

// `line` with its `*HHHH` checksum appended.
std::string with_checksum(std::string_view line);

}  // namespace robuter::ctl
