// open(2) + termios raw mode for the pan-tilt's port; hang-ups close it without throwing.
#include "modules/ptu/unit_port.hpp"

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

namespace robuter::ptu {

namespace {
constexpr std::array<std::pair<unsigned, speed_t>, 11> kRates{{
    {1200, B1200}, {2400, B2400}, {4800, B4800}, {9600, B9600}, {19200, B19200}, {38400, B38400},
    {57600, B57600}, {115200, B115200}, {230400, B230400}, {460800, B460800}, {921600, B921600},
}};
}  // namespace

bool UnitPort::valid_baud(unsigned baud) {
  for (const auto& [b, r] : kRates)
    if (b == baud) return true;
  return false;
}

UnitPort::UnitPort(std::string device, unsigned baud)
    : device_(std::move(device)), baud_(baud), label_("pan-tilt " + device_) {
  if (!valid_baud(baud_)) {
    error_ = "unsupported rate " + std::to_string(baud_);
    return;
  }
  if (!open_device()) error_ = "cannot open " + device_ + ": " + error_buf_;
}

UnitPort::~UnitPort() { close_device(); }

bool UnitPort::open_device() {
  const int fd = ::open(device_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    std::snprintf(error_buf_, sizeof error_buf_, "%s", std::strerror(errno));
    return false;
  }
  termios t{};
  if (tcgetattr(fd, &t) == 0) {
    cfmakeraw(&t);
    speed_t rate = B9600;
    for (const auto& [b, r] : kRates)
      if (b == baud_) rate = r;
    cfsetispeed(&t, rate);
    cfsetospeed(&t, rate);
    t.c_cflag |= CLOCAL | CREAD;
    t.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | PARENB | CRTSCTS);
    tcsetattr(fd, TCSANOW, &t);
  }
  in_fd_ = out_fd_ = fd;
  connected_ = true;
  error_buf_[0] = '\0';
  return true;
}

void UnitPort::close_device() {
  if (in_fd_ >= 0) ::close(in_fd_);
  in_fd_ = out_fd_ = -1;
  connected_ = false;
}

// Why close first: a descriptor left after a hang-up only ever answers EIO.
bool UnitPort::reopen() {
  if (connected_) return true;
  close_device();
  return open_device();
}

}  // namespace robuter::ptu
