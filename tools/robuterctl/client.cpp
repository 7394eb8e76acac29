// Raw terminal set-up and line reading with a deadline.
#include "tools/robuterctl/client.hpp"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace robuter::ctl {

namespace {
speed_t to_speed(unsigned baud) {
  switch (baud) {
    case 9600: return B9600;
    case 19200: return B19200;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    case 230400: return B230400;
    default: return B9600;
  }
}
}  // namespace

Client::Client(const std::string& path, unsigned baud) {
  fd_ = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (fd_ < 0) {
    error_ = "cannot open " + path + ": " + std::strerror(errno);
    return;
  }
  termios t{};
  if (tcgetattr(fd_, &t) == 0) {
    cfmakeraw(&t);
    if (baud) {
      cfsetispeed(&t, to_speed(baud));
      cfsetospeed(&t, to_speed(baud));
    }
    tcsetattr(fd_, TCSANOW, &t);
  }
}

Client::~Client() {
  if (fd_ >= 0) ::close(fd_);
}

bool Client::send_raw(std::string_view bytes) {
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

std::optional<std::string> Client::read_line(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const auto cr = pending_.find_first_of("\r\n");
    if (cr != std::string::npos) {
      std::string line = pending_.substr(0, cr);
      std::size_t skip = cr + 1;
      if (pending_[cr] == '\r' && skip < pending_.size() && pending_[skip] == '\n') ++skip;
      pending_.erase(0, skip);
      return line;
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return std::nullopt;
    pollfd p{fd_, POLLIN, 0};
    const int n = ::poll(&p, 1, static_cast<int>(left.count()));
    if (n <= 0) continue;
    char buf[4096];
    const ssize_t got = ::read(fd_, buf, sizeof buf);
    if (got > 0) pending_.append(buf, static_cast<std::size_t>(got));
    else if (got == 0 || (errno != EAGAIN && errno != EINTR)) return std::nullopt;
  }
}

std::size_t Client::drain(std::chrono::milliseconds quiet) {
  std::size_t lines = 0;
  while (read_line(quiet)) ++lines;
  pending_.clear();
  return lines;
}

}  // namespace robuter::ctl
