// Standard input/output made non-blocking.
#include "hal/link/stdio_link.hpp"

#include <fcntl.h>
#include <unistd.h>

namespace robuter::hal {

StdioLink::StdioLink() {
  in_fd_ = STDIN_FILENO;
  out_fd_ = STDOUT_FILENO;
  fcntl(in_fd_, F_SETFL, fcntl(in_fd_, F_GETFL) | O_NONBLOCK);
  fcntl(out_fd_, F_SETFL, fcntl(out_fd_, F_GETFL) | O_NONBLOCK);
  connected_ = true;
}

}  // namespace robuter::hal
