// SPDX-License-Identifier: GPL-3.0-or-later
// A serial device as a ByteStream that survives the device going away and coming back.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "hal/api/byte_stream.hpp"
#include "hal/linux/serial_settings.hpp"

namespace robuter::hal {

// The periodic path only reads, writes and swaps descriptors (no allocation, no blocking call,
// no exception). Opening, configuring and closing a device — calls that may sleep in a USB
// driver or wait for output to drain — run on a helper thread that wakes every retry_ms:
// while the link is lost it closes the dead descriptor and tries to open the path again;
// while connected it checks that the path still names the device it opened (a removed node
// or a new one at the same path, e.g. a USB adapter re-plugged, counts as lost).
// Why not LibSerial: its SerialPort destructor (noexcept) throws when the device has gone
// (tcsetattr → EIO), which aborts the process; it also allocates and throws on every open.
class SerialStream final : public ByteStream {
 public:
  // Opens `device` with `s` now; on failure error() says why and the stream is not usable.
  // `label` names it in logs ("serial /dev/robuter-link").
  SerialStream(std::string device, const SerialSettings& s, std::string label);
  ~SerialStream() override;
  SerialStream(const SerialStream&) = delete;
  SerialStream& operator=(const SerialStream&) = delete;

  const char* name() const override { return label_.c_str(); }
  int fd() const override { return connected_ ? fd_ : -1; }
  IoResult read(std::span<std::uint8_t> out) override;
  IoResult write(std::span<const std::uint8_t> in) override;
  // Takes the descriptor the helper thread opened, if any; never blocks.
  bool reopen() override;
  bool connected() const override { return connected_; }
  // "hung up", "device node removed or replaced" or the errno's text; null before any loss.
  const char* loss_reason() const override;
  int loss_errno() const { return loss_errno_; }

  const std::optional<std::string>& error() const { return error_; }
  const std::string& device() const { return device_; }
  std::uint32_t losses() const { return losses_; }    // times the device was lost, count
  std::uint32_t reopens() const { return reopens_; }  // times it came back, count
  // Open attempts that failed since the last loss, count (helper thread; relaxed read).
  std::uint32_t failed_attempts() const { return failed_attempts_.load(std::memory_order_relaxed); }

 private:
  enum State : int { kConnected = 0, kLost = 1, kReady = 2 };
  // Drops the descriptor (handed to the helper thread to close) and records why.
  void lose(int err);
  // The helper thread's loop.
  void helper();
  // Opens and configures the device; the descriptor or -1 with errno set.
  int open_device();

  std::string device_;                      // path, e.g. /dev/robuter-link
  SerialSettings settings_;                 // line settings, re-applied on every open
  std::string label_;                       // name in logs
  std::optional<std::string> error_;        // why the start-up open failed
  int fd_ = -1;                             // the periodic path's descriptor, -1 while lost
  bool connected_ = false;                  // fd_ is usable
  int loss_errno_ = 0;                      // why the device was last lost (errno; EPIPE hung up, ESTALE node gone)
  std::uint32_t losses_ = 0;                // device lost, count
  std::uint32_t reopens_ = 0;               // device back, count
  std::atomic<int> state_{kLost};           // who owns the hand-over slot (State)
  std::atomic<int> handed_fd_{-1};          // lost descriptor to close, or new one to take
  std::atomic<bool> stale_{false};          // helper thread: the path no longer names our device
  std::atomic<std::uint32_t> failed_attempts_{0};  // open attempts failed since the loss, count
  std::uint64_t opened_dev_ = 0;            // helper thread: st_rdev of the open device
  std::uint64_t opened_ino_ = 0;            // helper thread: inode of the open device's node
  std::mutex mutex_;                        // guards stop_ (helper's sleep)
  std::condition_variable wake_;            // ends the helper's sleep at shutdown
  bool stop_ = false;                       // the helper thread must end
  std::thread thread_;                      // the helper thread
};

}  // namespace robuter::hal
