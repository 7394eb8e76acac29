// SPDX-License-Identifier: GPL-3.0-or-later
// A writer outside the kernel: takes what the kernel handed over, writes it as a file, counts.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include "kernel/handoff.hpp"

namespace robuter {

// The frame of a file writer fed by the kernel through `Box` (a OneSlot, or a mailbox with its
// take(), release() and dropped()): each value taken is written by the derived class's write()
// — blocking I/O, so on its own thread (robuterd: start()), or between ticks when a test steps a
// virtual clock (drain()) — and counted. The thread calls write(): a derived class stops it in
// its own destructor (stop()), before its members go.
template <class Box>
class DrainWriter {
 public:
  using Item = std::remove_pointer_t<decltype(std::declval<Box&>().take())>;  // what the box holds

  virtual ~DrainWriter() = default;
  DrainWriter(const DrainWriter&) = delete;
  DrainWriter& operator=(const DrainWriter&) = delete;

  // Why: writes the waiting value, if any; true if a file was written.
  bool drain() {
    Item* item = box_.take();
    if (item == nullptr) return false;
    const std::optional<std::string> error = write(*item);
    box_.release();
    if (error) {
      // Not the kernel's thread: a message on stderr costs the robot nothing.
      if (failed_.fetch_add(1) == 0) std::fprintf(stderr, "robuterd: %s: %s\n", what_, error->c_str());
      return false;
    }
    written_.fetch_add(1);
    return true;
  }
  // Why: robuterd: drain every 10 ms on a thread of its own until stop().
  void start() { thread_.start([this] { return drain(); }); }
  // Why: joins the thread, then writes what is still waiting.
  void stop() {
    thread_.stop();
    drain();
  }
  bool running() const { return thread_.running(); }
  std::uint32_t written() const { return written_.load(); }
  std::uint32_t failed() const { return failed_.load(); }
  // Why: values dropped because the writer still held the last one (the box counts them).
  std::uint32_t dropped() const { return box_.dropped(); }
  const std::string& dir() const { return dir_; }

 protected:
  // `what` names the files in the error message (a literal); `dir` is their folder.
  DrainWriter(const char* what, std::string dir, Box& box) : what_(what), dir_(std::move(dir)), box_(box) {}
  // Writes `item` (blocking I/O); the error's text when it could not.
  virtual std::optional<std::string> write(Item& item) = 0;

  const char* what_;                       // what is written, for the error message
  std::string dir_;                        // folder of the files
  Box& box_;                               // where the kernel leaves values

 private:
  DrainThread thread_;                     // the writer thread (robuterd), or none (tests)
  std::atomic<std::uint32_t> written_{0};  // files written, count
  std::atomic<std::uint32_t> failed_{0};   // files that could not be written, count
};

}  // namespace robuter
