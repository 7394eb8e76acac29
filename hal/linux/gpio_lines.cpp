// SPDX-License-Identifier: GPL-3.0-or-later
// Line request on /dev/gpiochipN, non-blocking event drain and level read.
#include "hal/linux/gpio_lines.hpp"

#include <fcntl.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <utility>

namespace robuter::hal {

GpioLines::GpioLines(const std::string& chip, std::vector<std::uint32_t> bumper_lines,
                     std::vector<std::uint32_t> input_lines, bool active_low, std::uint32_t debounce_us)
    : bumper_count_(bumper_lines.size()), input_count_(input_lines.size()) {
  offsets_ = std::move(bumper_lines);
  offsets_.insert(offsets_.end(), input_lines.begin(), input_lines.end());
  gpio_v2_line_request req{};
  if (!gpio::build_request({offsets_, active_low, debounce_us, "robuterd"}, req)) {
    error_ = "gpio " + chip + ": between 1 and 32 lines must be configured (hardware.gpio.bumper_lines, input_lines)";
    return;
  }
  const int chip_fd = ::open(chip.c_str(), O_RDONLY | O_CLOEXEC);
  if (chip_fd < 0) {
    error_ = "gpio: cannot open chip " + chip + ": " + std::strerror(errno) +
             (errno == ENOENT ? " (no such GPIO character device on this machine: see `ls /dev/gpiochip*`, "
                                "`gpiodetect`, and [hardware.gpio] chip)"
                              : "");
    return;
  }
  if (::ioctl(chip_fd, GPIO_V2_GET_LINE_IOCTL, &req) != 0) {
    error_ = "gpio: chip " + chip + ": cannot request lines: " + std::strerror(errno) +
             (errno == EBUSY ? " (a line is held by another consumer: see `gpioinfo`)"
              : errno == EINVAL ? " (an offset is beyond the chip's lines: see `gpioinfo`)" : "");
    ::close(chip_fd);
    return;
  }
  ::close(chip_fd);  // the line request lives on without the chip descriptor
  line_fd_ = req.fd;
  ::fcntl(line_fd_, F_SETFL, ::fcntl(line_fd_, F_GETFL) | O_NONBLOCK);
  ::fcntl(line_fd_, F_SETFD, FD_CLOEXEC);
  poll();  // the levels at start-up
}

GpioLines::GpioLines(int line_fd, std::vector<std::uint32_t> bumper_lines, std::vector<std::uint32_t> input_lines)
    : bumper_count_(bumper_lines.size()), input_count_(input_lines.size()), line_fd_(line_fd) {
  offsets_ = std::move(bumper_lines);
  offsets_.insert(offsets_.end(), input_lines.begin(), input_lines.end());
  ::fcntl(line_fd_, F_SETFL, ::fcntl(line_fd_, F_GETFL) | O_NONBLOCK);
}

GpioLines::~GpioLines() {
  if (line_fd_ >= 0) ::close(line_fd_);
}

// Why events and then values: the events catch a pulse shorter than the poll period; the
// values stay right even if the kernel's event buffer overflowed.
void GpioLines::poll() const {
  if (line_fd_ < 0) return;
  std::array<gpio_v2_line_event, 16> events{};
  for (int round = 0; round < 4; ++round) {  // bounded: at most 64 events per poll
    const ssize_t n = ::read(line_fd_, events.data(), sizeof events);
    if (n < 0) {
      if (errno != EAGAIN && errno != EINTR) ++bad_events_;
      break;
    }
    const auto count = static_cast<std::size_t>(n) / sizeof(gpio_v2_line_event);
    for (std::size_t i = 0; i < count; ++i)
      if (!gpio::apply_event(events[i], offsets_, state_)) ++bad_events_;
    if (count < events.size()) break;
  }
  gpio_v2_line_values v{};
  v.mask = offsets_.size() >= 64 ? ~0ULL : (1ULL << offsets_.size()) - 1;
  if (::ioctl(line_fd_, GPIO_V2_LINE_GET_VALUES_IOCTL, &v) == 0) state_.level = gpio::decode_values(v, offsets_.size());
}

std::uint32_t GpioLines::pressed() const {
  poll();
  const std::uint32_t mask = bumper_count_ >= 32 ? ~0U : (1U << bumper_count_) - 1;
  return gpio::sample(state_, mask);
}

std::uint32_t GpioLines::levels() const {
  poll();
  const std::uint32_t all = offsets_.size() >= 32 ? ~0U : (1U << offsets_.size()) - 1;
  const std::uint32_t bumpers = bumper_count_ >= 32 ? ~0U : (1U << bumper_count_) - 1;
  return bumper_count_ >= 32 ? 0 : gpio::sample(state_, all & ~bumpers) >> bumper_count_;
}

}  // namespace robuter::hal
