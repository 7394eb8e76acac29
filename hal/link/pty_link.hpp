// SPDX-License-Identifier: GPL-3.0-or-later
// A pseudo-terminal the server creates; PATH becomes a symbolic link to its slave side.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "hal/link/fd_stream.hpp"

namespace robuter::hal {

class PtyLink final : public FdStream {
 public:
  enum class Mode : std::uint8_t {
    // A client is attached while the slave is open (the master stops reporting a hang-up):
    // the pan-tilt emulator's pty and test devices.
    hang_up,
    // A command link (docs/PROTOCOL.md, "Sessions"): the server holds the slave open itself, so
    // what a client wrote is read even after it closed; client opens and closes are watched
    // (inotify on /dev/pts/N) and reported as sessions; PATH is guarded by an flock on
    // PATH.lock, so a second server on the same path is refused.
    sessions,
  };

  // Creates the pty and the link at `path`; on failure error() says why.
  explicit PtyLink(std::string path, Mode mode = Mode::hang_up);
  ~PtyLink() override;
  PtyLink(const PtyLink&) = delete;
  PtyLink& operator=(const PtyLink&) = delete;

  const char* name() const override { return label_.c_str(); }
  // hang_up: a client is attached when the master no longer reports a hang-up. sessions: the
  // stream is always usable.
  bool reopen() override;
  ClientEvent next_client_event() override;
  int event_fd() const override { return inotify_fd_; }
  bool client_present() const override { return mode_ == Mode::sessions ? clients_ > 0 : connected_; }
  void discard_unread_output() override;
  const std::optional<std::string>& error() const { return error_; }
  const std::string& slave_name() const { return slave_; }
  // Clients holding the slave now (sessions mode), count.
  int clients() const { return clients_; }

 private:
  // Takes PATH.lock (flock, non-blocking); false with error_ set when another process holds it.
  bool lock_path();
  // Holds the slave open and watches it for client opens and closes (sessions mode).
  bool watch_clients();
  // Sets the line raw again (a client may have changed it).
  void make_raw();

  std::string path_;                  // the symbolic link clients open
  std::string slave_;                 // /dev/pts/N
  std::string label_;                 // "pty PATH"
  std::string lock_path_;             // PATH.lock (sessions mode)
  Mode mode_;                         // how clients are told apart
  int lock_fd_ = -1;                  // the locked PATH.lock, -1 none
  int slave_fd_ = -1;                 // the server's own descriptor of the slave (sessions), -1 none
  int inotify_fd_ = -1;               // client opens and closes of the slave (sessions), -1 none
  int clients_ = 0;                   // clients holding the slave now (sessions), count
  std::array<std::uint8_t, 1024> events_{};  // inotify events read, not yet reported
  std::size_t events_len_ = 0, events_pos_ = 0;  // unreported events are events_[pos, len)
  std::optional<std::string> error_;  // why creation failed
};

}  // namespace robuter::hal
