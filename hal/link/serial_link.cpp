// LibSerial opens and configures the device; reads and writes go through its descriptor.
#include "hal/link/serial_link.hpp"

#include <fcntl.h>
#include <libserial/SerialPort.h>
#include <time.h>
#include <unistd.h>

#include <array>
#include <utility>

namespace robuter::hal {

namespace {
constexpr std::array<std::pair<unsigned, LibSerial::BaudRate>, 12> kRates{{
    {1200, LibSerial::BaudRate::BAUD_1200},     {2400, LibSerial::BaudRate::BAUD_2400},
    {4800, LibSerial::BaudRate::BAUD_4800},     {9600, LibSerial::BaudRate::BAUD_9600},
    {19200, LibSerial::BaudRate::BAUD_19200},   {38400, LibSerial::BaudRate::BAUD_38400},
    {57600, LibSerial::BaudRate::BAUD_57600},   {115200, LibSerial::BaudRate::BAUD_115200},
    {230400, LibSerial::BaudRate::BAUD_230400}, {460800, LibSerial::BaudRate::BAUD_460800},
    {500000, LibSerial::BaudRate::BAUD_500000}, {921600, LibSerial::BaudRate::BAUD_921600},
}};
}  // namespace

bool SerialLink::valid_baud(unsigned baud) {
  for (const auto& [b, r] : kRates)
    if (b == baud) return true;
  return false;
}

SerialLink::SerialLink(std::string device, unsigned baud)
    : device_(std::move(device)), baud_(baud), label_("serial " + device_) {
  open_device();
}

SerialLink::~SerialLink() = default;

bool SerialLink::open_device() {
  LibSerial::BaudRate rate = LibSerial::BaudRate::BAUD_9600;
  for (const auto& [b, r] : kRates)
    if (b == baud_) rate = r;
  try {
    auto port = std::make_unique<LibSerial::SerialPort>();
    port->Open(device_);
    port->SetBaudRate(rate);
    port->SetCharacterSize(LibSerial::CharacterSize::CHAR_SIZE_8);
    port->SetParity(LibSerial::Parity::PARITY_NONE);
    port->SetStopBits(LibSerial::StopBits::STOP_BITS_1);
    port->SetFlowControl(LibSerial::FlowControl::FLOW_CONTROL_NONE);
    const int fd = port->GetFileDescriptor();
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
    in_fd_ = out_fd_ = fd;
    port_ = std::move(port);
    connected_ = true;
    error_.reset();
    return true;
  } catch (const std::exception& e) {
    error_ = "cannot open " + device_ + ": " + e.what();
    port_.reset();
    in_fd_ = out_fd_ = -1;
    connected_ = false;
    return false;
  }
}

bool SerialLink::reopen() {
  if (connected_) return true;
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  const long long now_ms = ts.tv_sec * 1000LL + ts.tv_nsec / 1'000'000;
  if (now_ms - last_attempt_ms_ < kRetryMs) return false;
  last_attempt_ms_ = now_ms;
  port_.reset();  // close a device that went away before trying again
  in_fd_ = out_fd_ = -1;
  return open_device();
}

}  // namespace robuter::hal
