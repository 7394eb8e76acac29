// SPDX-License-Identifier: GPL-3.0-or-later
// Raw terminal set-up and line reading with a deadline.
#include "tools/robuterctl/client.hpp"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <fmt/format.h>

#include <csignal>
#include <cerrno>
#include <cstring>
#include <ctime>

namespace robuter::ctl {

namespace {
volatile std::sig_atomic_t g_interrupted = 0;
void on_sigint(int) { g_interrupted = 1; }

std::optional<speed_t> to_speed(unsigned baud) {
  switch (baud) {
    case 1200: return B1200;
    case 2400: return B2400;
    case 4800: return B4800;
    case 9600: return B9600;
    case 19200: return B19200;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    case 230400: return B230400;
    case 460800: return B460800;
    case 921600: return B921600;
    default: return std::nullopt;
  }
}
}  // namespace

bool baud_supported(unsigned baud) { return to_speed(baud).has_value(); }
bool interrupted() { return g_interrupted != 0; }
void clear_interrupted() { g_interrupted = 0; }
void catch_interrupt() {
  struct sigaction sa {};
  sa.sa_handler = on_sigint;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;  // no SA_RESTART: a wait returns at once
  sigaction(SIGINT, &sa, nullptr);
}

std::string visible(std::string_view s) {
  std::string out;
  for (unsigned char c : s) out += (c >= 32 && c < 127) ? std::string(1, static_cast<char>(c)) : fmt::format("\\x{:02x}", c);
  return out;
}

Client::Client(const std::string& path, unsigned baud) {
  fd_ = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
  if (fd_ < 0) {
    open_errno_ = errno;
    error_ = "cannot open " + path + ": " + std::strerror(errno);
    return;
  }
  termios t{};
  if (tcgetattr(fd_, &t) == 0) {
    cfmakeraw(&t);
    if (baud) {
      const auto speed = to_speed(baud);
      if (!speed) {
        error_ = fmt::format("--baud {}: not a rate this device can be set to", baud);
        return;
      }
      cfsetispeed(&t, *speed);
      cfsetospeed(&t, *speed);
    }
    tcsetattr(fd_, TCSANOW, &t);
  }
}

Client::~Client() {
  if (fd_ >= 0) ::close(fd_);
}

void Client::log_line(char dir, std::string_view text) {
  if (!log_) return;
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  tm local{};
  localtime_r(&ts.tv_sec, &local);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%H:%M:%S", &local);
  fmt::print(log_, "{}.{:03d} {} {}\n", stamp, static_cast<int>(ts.tv_nsec / 1000000), dir, visible(text));
  std::fflush(log_);
}

void Client::note(std::string_view what) { log_line('#', what); }

std::size_t Client::flush_stale(std::chrono::milliseconds quiet) {
  std::size_t dropped = 0;
  ::tcflush(fd_, TCIFLUSH);
  const auto deadline = std::chrono::steady_clock::now() + quiet;
  for (;;) {
    char buf[4096];
    const ssize_t got = ::read(fd_, buf, sizeof buf);
    if (got > 0) {
      dropped += static_cast<std::size_t>(got);
      continue;
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) break;
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(left.count())) <= 0) break;
  }
  if (dropped && log_) note(fmt::format("{} stale bytes dropped on open", dropped));
  pending_.clear();
  after_cr_ = false;
  return dropped;
}

bool Client::send_raw(std::string_view bytes) {
  if (log_) {
    std::string_view rest = bytes;
    while (!rest.empty()) {
      const auto cr = rest.find('\r');
      log_line('>', rest.substr(0, cr));
      if (cr == std::string_view::npos) break;
      rest.remove_prefix(cr + 1);
    }
  }
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno == EAGAIN) {
        pollfd p{fd_, POLLOUT, 0};
        ::poll(&p, 1, 100);
        continue;
      }
      return false;
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

bool Client::pump() {
  for (;;) {
    char buf[4096];
    const ssize_t got = ::read(fd_, buf, sizeof buf);
    if (got > 0) {
      pending_.append(buf, static_cast<std::size_t>(got));
      if (static_cast<std::size_t>(got) < sizeof buf) return true;
      continue;
    }
    if (got == 0) return false;
    return errno == EAGAIN || errno == EINTR;
  }
}

std::optional<std::string> Client::next_line() {
  for (;;) {
    if (after_cr_ && !pending_.empty()) {
      if (pending_[0] == '\n') pending_.erase(0, 1);
      after_cr_ = false;
    }
    const auto end = pending_.find_first_of("\r\n");
    if (end == std::string::npos) return std::nullopt;
    std::string line = pending_.substr(0, end);
    std::size_t skip = end + 1;
    after_cr_ = pending_[end] == '\r';
    if (after_cr_ && skip < pending_.size()) {
      if (pending_[skip] == '\n') ++skip;
      after_cr_ = false;
    }
    pending_.erase(0, skip);
    if (line.empty()) continue;  // no reply is empty: the second half of a CR LF, or noise
    log_line('<', line);
    return line;
  }
}

std::optional<std::string> Client::read_line(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    if (auto line = next_line()) return line;
    if (interrupted()) return std::nullopt;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return std::nullopt;
    pollfd p[2] = {{fd_, POLLIN, 0}, {watch_fd_, POLLIN, 0}};
    const int n = ::poll(p, watch_fd_ >= 0 ? 2 : 1, static_cast<int>(left.count()));
    if (n <= 0) continue;
    if (watch_fd_ >= 0 && (p[1].revents & POLLIN) && on_watch_) on_watch_();
    if (p[0].revents & (POLLIN | POLLHUP | POLLERR)) {
      if (!pump()) return next_line();
    }
  }
}

void Client::idle(std::chrono::milliseconds time) {
  const auto deadline = std::chrono::steady_clock::now() + time;
  for (;;) {
    if (interrupted()) return;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return;
    pollfd p{watch_fd_, POLLIN, 0};
    const int n = ::poll(&p, watch_fd_ >= 0 ? 1 : 0, static_cast<int>(left.count()));
    if (n > 0 && on_watch_) on_watch_();
  }
}

std::size_t Client::drain(std::chrono::milliseconds quiet) {
  std::size_t lines = 0;
  while (read_line(quiet)) ++lines;
  pending_.clear();
  after_cr_ = false;
  return lines;
}

}  // namespace robuter::ctl
