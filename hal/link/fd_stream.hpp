// SPDX-License-Identifier: GPL-3.0-or-later
// A ByteStream over a non-blocking descriptor pair: the common part of pty, serial and stdio links.
#pragma once

#include "hal/api/byte_stream.hpp"

namespace robuter::hal {

class FdStream : public ByteStream {
 public:
  int fd() const override { return connected_ ? in_fd_ : -1; }
  IoResult read(std::span<std::uint8_t> out) override;
  IoResult write(std::span<const std::uint8_t> in) override;
  bool connected() const override { return connected_; }

 protected:
  int in_fd_ = -1;          // descriptor read
  int out_fd_ = -1;         // descriptor written (the same as in_fd_ but for stdio)
  bool connected_ = false;  // a peer is attached
};

}  // namespace robuter::hal
