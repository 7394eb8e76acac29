// A serial device (8N1 at a given baud) through LibSerial, re-opened when it comes back.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "hal/link/fd_stream.hpp"

namespace LibSerial {
class SerialPort;
}

namespace robuter::hal {

class SerialLink final : public FdStream {
 public:
  // Opens `device` at `baud`; on failure error() says why (the link retries in reopen()).
  SerialLink(std::string device, unsigned baud);
  ~SerialLink() override;
  SerialLink(const SerialLink&) = delete;
  SerialLink& operator=(const SerialLink&) = delete;

  const char* name() const override { return label_.c_str(); }
  bool reopen() override;
  const std::optional<std::string>& error() const { return error_; }
  static constexpr long long kRetryMs = 1000;   // a missing device is looked for once a second
  // True when `baud` is a rate LibSerial supports.
  static bool valid_baud(unsigned baud);

 private:
  // Opens and configures the device; false with error_ set on failure.
  bool open_device();

  std::string device_;                          // e.g. /dev/ttyUSB0
  unsigned baud_;                               // bits per second
  std::string label_;                           // "serial DEV"
  std::unique_ptr<LibSerial::SerialPort> port_; // the open device, if any
  std::optional<std::string> error_;            // why the last open failed
  long long last_attempt_ms_ = 0;               // monotonic time of the last open attempt, ms
};

}  // namespace robuter::hal
