// SPDX-License-Identifier: GPL-3.0-or-later
// A pty pair standing in for a serial device: DEV is a symbolic link to the slave, and the
// test unplugs (closes the master, removes DEV) and re-plugs (a new pty, DEV points at it).
#pragma once

#include <string>
#include <string_view>

namespace robuter::test {

class FakeSerialDevice {
 public:
  // Creates a pty and the link `path` to its slave; ok() tells whether it worked.
  explicit FakeSerialDevice(std::string path);
  ~FakeSerialDevice();
  FakeSerialDevice(const FakeSerialDevice&) = delete;
  FakeSerialDevice& operator=(const FakeSerialDevice&) = delete;

  bool ok() const { return master_ >= 0; }
  // The device goes away: the master is closed (the slave hangs up) and the link removed.
  void unplug();
  // A new device at the same path (a new pty, a new inode); `keep_old` leaves the previous
  // master open, so the old slave never hangs up (only the node at the path changed).
  bool plug(bool keep_old = false);
  // Writes bytes as the far end of the line.
  bool send(std::string_view bytes);
  // Reads what arrived, without blocking.
  std::string receive();
  const std::string& slave() const { return slave_; }
  int master() const { return master_; }

 private:
  std::string path_;   // the link the firmware opens
  std::string slave_;  // /dev/pts/N of the current pty
  int master_ = -1;    // current master, -1 when unplugged
  int old_master_ = -1;  // a previous master kept open by plug(true)
};

}  // namespace robuter::test
