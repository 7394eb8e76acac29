// SPDX-License-Identifier: GPL-3.0-or-later
// The last map pose kept across restarts: its text file, and the thread that writes it.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>

#include "kernel/handoff.hpp"

namespace robuter::localise {

// A map pose as the file keeps it (the protocol's units).
struct SavedPose {
  std::int32_t x = 0;      // 0.1 mm, map frame
  std::int32_t y = 0;      // 0.1 mm
  std::int32_t theta = 0;  // 0.01 degree, (-18000, 18000]
};

// The file: a header line `robuter-localise 1`, then `pose <x> <y> <theta>`; '#' comments.
std::string state_text(const SavedPose& p);
// Reads `path`: the pose, or why not ("FILE:LINE: message"; a missing file says so too).
std::optional<SavedPose> read_state_file(const std::string& path, std::string& why);
// Writes `path` whole or not at all (a temporary file renamed over it); false with `why`.
bool write_state_file(const std::string& path, const SavedPose& p, std::string& why);

// Writes each pose the module hands over (at most one a second while tracking) to the state file,
// on a thread of its own (robuterd) or between ticks (tests call drain()); the kernel never waits.
class StateFileWriter {
 public:
  explicit StateFileWriter(std::string path) : path_(std::move(path)) {}
  ~StateFileWriter() { stop(); }
  StateFileWriter(const StateFileWriter&) = delete;
  StateFileWriter& operator=(const StateFileWriter&) = delete;

  // Kernel side: hands `p` over (dropped, and counted, while the last one is being written).
  void post(const SavedPose& p);
  // Writer side: writes the pose waiting, if any; true when a file was written.
  bool drain();
  void start() { thread_.start([this] { return drain(); }); }
  void stop() {
    thread_.stop();
    drain();
  }
  std::uint32_t written() const { return written_.load(); }
  std::uint32_t failed() const { return failed_.load(); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;                       // the state file
  OneSlot<SavedPose> slot_;                // the pose handed over
  DrainThread thread_;                     // the writer thread (robuterd), or none (tests)
  std::atomic<std::uint32_t> written_{0};  // files written, count
  std::atomic<std::uint32_t> failed_{0};   // writes that failed, count
};

}  // namespace robuter::localise
