// The pan-tilt unit's serial port: a raw tty opened with termios, closed quietly, re-opened on demand.
#pragma once

#include <string>

#include "hal/link/fd_stream.hpp"

namespace robuter::ptu {

// Why not hal::SerialLink: LibSerial's SerialPort throws from its destructor when the device has
// gone away (EIO on closing a pty whose far end closed, or an unplugged adapter), which would end
// the firmware at shutdown after the unit was unplugged. This port uses open/termios/close only;
// nothing here throws or allocates after construction.
class UnitPort final : public hal::FdStream {
 public:
  // Opens `device` raw, 8N1, at `baud`; error() says why not (reopen() tries again).
  UnitPort(std::string device, unsigned baud);
  ~UnitPort() override;
  UnitPort(const UnitPort&) = delete;
  UnitPort& operator=(const UnitPort&) = delete;

  const char* name() const override { return label_.c_str(); }
  // Opens the device again if it was lost; true when usable.
  bool reopen() override;
  const std::string& error() const { return error_; }
  // True when `baud` is a rate termios knows.
  static bool valid_baud(unsigned baud);

 private:
  bool open_device();
  void close_device();

  std::string device_;  // e.g. /dev/ttyUSB1
  unsigned baud_;       // bit/s
  std::string label_;   // "pan-tilt DEV"
  std::string error_;   // why the last open failed, empty when open
  char error_buf_[160] = {};  // reopen()'s failure text, kept without allocating
};

}  // namespace robuter::ptu
