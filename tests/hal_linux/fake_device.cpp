// SPDX-License-Identifier: GPL-3.0-or-later
// Pty creation, unplug and re-plug for the serial device tests.
#include "tests/hal_linux/fake_device.hpp"

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <cstdlib>

namespace robuter::test {

FakeSerialDevice::FakeSerialDevice(std::string path) : path_(std::move(path)) { plug(); }

FakeSerialDevice::~FakeSerialDevice() {
  unplug();
  if (old_master_ >= 0) ::close(old_master_);
}

void FakeSerialDevice::unplug() {
  if (master_ >= 0) ::close(master_);
  master_ = -1;
  ::unlink(path_.c_str());
}

bool FakeSerialDevice::plug(bool keep_old) {
  if (master_ >= 0) {
    if (keep_old) {
      if (old_master_ >= 0) ::close(old_master_);
      old_master_ = master_;
    } else {
      ::close(master_);
    }
    master_ = -1;
  }
  const int m = posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (m < 0 || grantpt(m) != 0 || unlockpt(m) != 0) return false;
  termios t{};
  tcgetattr(m, &t);
  cfmakeraw(&t);
  tcsetattr(m, TCSANOW, &t);
  slave_ = ptsname(m);
  ::unlink(path_.c_str());
  if (::symlink(slave_.c_str(), path_.c_str()) != 0) {
    ::close(m);
    return false;
  }
  master_ = m;
  return true;
}

bool FakeSerialDevice::send(std::string_view bytes) {
  return master_ >= 0 && ::write(master_, bytes.data(), bytes.size()) == static_cast<ssize_t>(bytes.size());
}

std::string FakeSerialDevice::receive() {
  std::string out;
  if (master_ < 0) return out;
  std::array<char, 512> buf{};
  for (;;) {
    const ssize_t n = ::read(master_, buf.data(), buf.size());
    if (n <= 0) break;
    out.append(buf.data(), static_cast<std::size_t>(n));
  }
  return out;
}

}  // namespace robuter::test
