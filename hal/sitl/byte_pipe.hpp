// SPDX-License-Identifier: GPL-3.0-or-later
// Two byte streams joined inside the process: what one end writes, the other reads (the
// simulated pan-tilt unit wired to the PTU module under --sim, no pty on the filesystem).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "hal/api/byte_stream.hpp"

namespace robuter::hal {

// The shared state of a pipe: one bounded ring per direction, sized once at start-up.
class BytePipeState;

// One end of an in-process pipe. Never blocks, never allocates after construction: a write
// takes what fits in the ring towards the other end, a read what is there. It has no
// descriptor (fd() is -1): its reader steps every tick (the PTU driver, the SimStepper's
// PtuPort), as the kernel is single-threaded.
class PipeEnd final : public ByteStream {
 public:
  PipeEnd(std::shared_ptr<BytePipeState> state, int side, std::string name);
  const char* name() const override { return name_.c_str(); }
  int fd() const override { return -1; }
  IoResult read(std::span<std::uint8_t> out) override;
  IoResult write(std::span<const std::uint8_t> in) override;
  // A hung-up pipe stays hung up until plug_in(): reopen() only reports.
  bool reopen() override { return connected(); }
  bool connected() const override;
  const char* loss_reason() const override;
  // The cable pulled (tests: a unit that goes away): both ends read and write `closed`, bytes in
  // flight are dropped.
  void unplug();
  // The cable put back: both ends usable again, empty.
  void plug_in();

 private:
  std::shared_ptr<BytePipeState> state_;  // the rings, shared with the other end
  int side_;                              // 0 or 1: which ring this end writes
  std::string name_;                      // for logs
};

// Makes the two ends of a pipe with `capacity` bytes each way: {first, second}.
std::pair<std::unique_ptr<PipeEnd>, std::unique_ptr<PipeEnd>> make_byte_pipe(std::string first_name,
                                                                              std::string second_name,
                                                                              std::size_t capacity = 1024);

}  // namespace robuter::hal
