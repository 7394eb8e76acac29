// SPDX-License-Identifier: GPL-3.0-or-later
// Serial device I/O on the periodic path; open, configure, watch and close on a helper thread.
#include "hal/linux/serial_stream.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <utility>

#include "hal/link/fd_io.hpp"

namespace robuter::hal {

namespace {
// Closes a descriptor without waiting for unsent output (a dead or flow-stopped line would
// otherwise hold close() for up to the driver's closing_wait, 30 s by default).
void close_quietly(int fd) {
  if (fd < 0) return;
  ::tcflush(fd, TCIOFLUSH);
  ::close(fd);
}
}  // namespace

SerialStream::SerialStream(std::string device, const SerialSettings& s, std::string label)
    : device_(std::move(device)), settings_(s), label_(std::move(label)) {
  if (!valid_baud(settings_.baud)) {
    error_ = label_ + ": unsupported rate " + std::to_string(settings_.baud) + " bit/s";
    return;
  }
  const int fd = open_device();
  if (fd < 0) {
    error_ = "cannot open " + device_ + ": " + std::strerror(errno);
    return;
  }
  fd_ = fd;
  connected_ = true;
  state_.store(kConnected, std::memory_order_release);
  thread_ = std::thread([this] { helper(); });
}

SerialStream::~SerialStream() {
  if (thread_.joinable()) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }
  close_quietly(fd_);
  close_quietly(handed_fd_.exchange(-1));
}

int SerialStream::open_device() {
  const int fd = ::open(device_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return -1;
  termios t{};
  if (::tcgetattr(fd, &t) != 0 || !encode_termios(settings_, t) || ::tcsetattr(fd, TCSANOW, &t) != 0) {
    const int err = errno;
    ::close(fd);
    errno = err;
    return -1;
  }
  ::tcflush(fd, TCIFLUSH);  // bytes from before this open belong to nobody
  struct stat st {};
  if (::fstat(fd, &st) == 0) {
    opened_dev_ = static_cast<std::uint64_t>(st.st_dev);
    opened_ino_ = static_cast<std::uint64_t>(st.st_ino);
  }
  return fd;
}

void SerialStream::lose(int err) {
  connected_ = false;
  loss_errno_ = err;
  ++losses_;
  failed_attempts_.store(0, std::memory_order_relaxed);
  handed_fd_.store(fd_, std::memory_order_relaxed);
  fd_ = -1;
  state_.store(kLost, std::memory_order_release);  // the helper closes it and looks again
}

IoResult SerialStream::read(std::span<std::uint8_t> out) {
  if (!connected_) return {0, true};
  if (stale_.load(std::memory_order_relaxed)) {
    lose(ESTALE);  // the helper found another node (or none) at the path
    return {0, true};
  }
  // A read of 0 is a hang-up: VMIN is 1, so an idle line says EAGAIN.
  return fd_io_result(FdCall::read, ::read(fd_, out.data(), out.size()), [this](int why) { lose(why); });
}

IoResult SerialStream::write(std::span<const std::uint8_t> in) {
  if (!connected_) return {0, true};
  return fd_io_result(FdCall::write, ::write(fd_, in.data(), in.size()), [this](int why) { lose(why); });
}

const char* SerialStream::loss_reason() const {
  if (losses_ == 0) return nullptr;
  if (loss_errno_ == EPIPE) return "hung up";
  if (loss_errno_ == ESTALE) return "device node removed or replaced";
  const char* d = strerrordesc_np(loss_errno_);
  return d ? d : "unknown error";
}

bool SerialStream::reopen() {
  if (connected_) return true;
  if (state_.load(std::memory_order_acquire) != kReady) return false;
  fd_ = handed_fd_.exchange(-1, std::memory_order_relaxed);
  connected_ = fd_ >= 0;
  if (!connected_) {  // never expected; look again rather than wait forever
    state_.store(kLost, std::memory_order_release);
    return false;
  }
  ++reopens_;
  state_.store(kConnected, std::memory_order_release);
  return true;
}

// Why a thread: open() of a USB serial device talks to the adapter and close() may wait for
// output to drain; neither belongs on the periodic path. One wake-up per retry_ms bounds the
// rate of open attempts and of path checks.
void SerialStream::helper() {
  // Signals (SIGINT/SIGTERM) go to the kernel's thread, whose idle wait they must interrupt.
  sigset_t all;
  sigfillset(&all);
  pthread_sigmask(SIG_BLOCK, &all, nullptr);
  const auto period = std::chrono::milliseconds(settings_.retry_ms);
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stop_) {
    wake_.wait_for(lock, period, [this] { return stop_; });
    if (stop_) break;
    const int state = state_.load(std::memory_order_acquire);
    if (state == kConnected) {
      // The node at the path must still be the one opened (removed or replaced: lost).
      struct stat st {};
      if (!stale_.load(std::memory_order_relaxed) &&
          (::stat(device_.c_str(), &st) != 0 || static_cast<std::uint64_t>(st.st_dev) != opened_dev_ ||
           static_cast<std::uint64_t>(st.st_ino) != opened_ino_))
        stale_.store(true, std::memory_order_relaxed);
    } else if (state == kLost) {
      close_quietly(handed_fd_.exchange(-1, std::memory_order_relaxed));
      const int fd = open_device();
      if (fd < 0) {
        failed_attempts_.fetch_add(1, std::memory_order_relaxed);
        continue;
      }
      stale_.store(false, std::memory_order_relaxed);
      handed_fd_.store(fd, std::memory_order_relaxed);
      state_.store(kReady, std::memory_order_release);  // the periodic path takes it in reopen()
    }
  }
}

}  // namespace robuter::hal
