// A client end of the command link: opens a pty or serial device raw, sends lines, reads replies.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace robuter::ctl {

class Client {
 public:
  // Opens `path` raw (8-bit, no echo); error() says why not.
  explicit Client(const std::string& path, unsigned baud = 0);
  ~Client();
  Client(const Client&) = delete;
  Client& operator=(const Client&) = delete;

  const std::optional<std::string>& error() const { return error_; }
  // Writes every byte of `bytes` (blocking until written or the link fails).
  bool send_raw(std::string_view bytes);
  // Writes `line` and the terminator CR.
  bool send_line(std::string_view line) { return send_raw(std::string(line) + "\r"); }
  // The next reply line without its terminator, or nullopt after `timeout`.
  std::optional<std::string> read_line(std::chrono::milliseconds timeout);
  // Reads and discards until nothing arrives for `quiet`; returns the lines dropped.
  std::size_t drain(std::chrono::milliseconds quiet);
  int fd() const { return fd_; }

 private:
  int fd_ = -1;                        // the open device
  std::string pending_;                // bytes read past the last full line
  std::optional<std::string> error_;   // why opening failed
};

}  // namespace robuter::ctl
