// SPDX-License-Identifier: GPL-3.0-or-later
// Standard input and output as a command link (scripts, pipes, a terminal).
#pragma once

#include "hal/link/fd_stream.hpp"

namespace robuter::hal {

class StdioLink final : public FdStream {
 public:
  StdioLink();
  const char* name() const override { return "stdio"; }
  // Standard input does not come back after EOF.
  bool reopen() override { return connected_; }
  // Standard output stays writable after standard input's EOF: the replies to lines read before
  // it (some may wait for a command's owner to run) still go out.
  IoResult write(std::span<const std::uint8_t> in) override;
};

}  // namespace robuter::hal
