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
};

}  // namespace robuter::hal
