// SPDX-License-Identifier: GPL-3.0-or-later
// A client end of the command link: opens a pty or serial device raw, sends lines, reads replies.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace robuter::ctl {

// The baud rates a serial device can be set to; false for anything else.
bool baud_supported(unsigned baud);

// Set by SIGINT once `catch_interrupt()` installed the handler: waits return early.
bool interrupted();
void clear_interrupted();
void catch_interrupt();

class Client {
 public:
  // Opens `path` raw (8-bit, no echo); error() says why not (with the system's reason).
  explicit Client(const std::string& path, unsigned baud = 0);
  ~Client();
  Client(const Client&) = delete;
  Client& operator=(const Client&) = delete;

  const std::optional<std::string>& error() const { return error_; }
  // errno of a failed open (0 when it opened).
  int open_errno() const { return open_errno_; }
  // Drops what an earlier client left unread: the device's input queue, then whatever arrives
  // within `quiet`. Returns the bytes dropped.
  std::size_t flush_stale(std::chrono::milliseconds quiet);
  // Writes every byte of `bytes` (blocking until written or the link fails).
  bool send_raw(std::string_view bytes);
  // Writes `line` and the terminator CR.
  bool send_line(std::string_view line) { return send_raw(std::string(line) + "\r"); }
  // The next line without its terminator (CR, LF or CR LF; empty lines skipped), or nullopt after
  // `timeout`, on end of file, or when interrupted().
  std::optional<std::string> read_line(std::chrono::milliseconds timeout);
  // Reads what the device holds now without waiting; false on end of file or a failed read.
  bool pump();
  // A complete line already read, if any.
  std::optional<std::string> next_line();
  // Reads and discards until nothing arrives for `quiet`; returns the lines dropped.
  std::size_t drain(std::chrono::milliseconds quiet);
  // Waits `time` while still serving the watched descriptor (see watch()).
  void idle(std::chrono::milliseconds time);
  int fd() const { return fd_; }

  // While waiting for the link, also wait for `fd` (the terminal) and call `on_ready` when it
  // is readable: the stop key works while a reply is awaited.
  void watch(int fd, std::function<void()> on_ready) {
    watch_fd_ = fd;
    on_watch_ = std::move(on_ready);
  }
  // Every line sent and received, with the time, goes to `log` (nullptr: none).
  void set_log(std::FILE* log) { log_ = log; }
  void note(std::string_view what);  // a remark in the transcript

 private:
  void log_line(char dir, std::string_view text);
  int fd_ = -1;                        // the open device
  int open_errno_ = 0;
  std::string pending_;                // bytes read past the last full line
  bool after_cr_ = false;              // the last line ended with CR: a leading LF belongs to it
  std::optional<std::string> error_;   // why opening failed
  int watch_fd_ = -1;
  std::function<void()> on_watch_;
  std::FILE* log_ = nullptr;
};

// `bytes` with control and 8-bit bytes written \xHH.
std::string visible(std::string_view bytes);

}  // namespace robuter::ctl
