// SPDX-License-Identifier: GPL-3.0-or-later
// The in-process pipe that wires the simulated pan-tilt unit to the PTU module under --sim:
// bytes cross both ways, a full ring takes what fits, an unplugged pipe reads closed, and the
// emulator answers over it as over its pty.
#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "hal/sitl/byte_pipe.hpp"
#include "hal/sitl/ptu_port.hpp"

namespace robuter::hal {
namespace {

std::span<const std::uint8_t> bytes(std::string_view s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

std::string read_all(ByteStream& s) {
  std::string out;
  std::uint8_t buf[7];  // small: reads wrap round the ring
  for (;;) {
    const IoResult r = s.read(buf);
    out.append(reinterpret_cast<const char*>(buf), r.bytes);
    if (r.bytes < sizeof buf) return out;
  }
}

TEST(BytePipe, BytesCrossBothWaysInOrder) {
  auto [a, b] = make_byte_pipe("a", "b", 16);
  EXPECT_STREQ(a->name(), "a");
  EXPECT_EQ(a->fd(), -1);
  EXPECT_TRUE(a->connected());
  EXPECT_EQ(a->write(bytes("PP\r")).bytes, 3u);
  EXPECT_EQ(b->write(bytes("* 12\r\n")).bytes, 6u);
  EXPECT_EQ(read_all(*b), "PP\r");
  EXPECT_EQ(read_all(*a), "* 12\r\n");
  EXPECT_EQ(read_all(*a), "");
  for (int i = 0; i < 10; ++i) {  // round and round the 16-byte ring
    EXPECT_EQ(a->write(bytes("0123456789")).bytes, 10u);
    EXPECT_EQ(read_all(*b), "0123456789");
  }
}

TEST(BytePipe, AFullRingTakesWhatFits) {
  auto [a, b] = make_byte_pipe("a", "b", 8);
  const IoResult w = a->write(bytes("0123456789"));
  EXPECT_EQ(w.bytes, 8u);
  EXPECT_FALSE(w.closed);
  EXPECT_EQ(a->write(bytes("x")).bytes, 0u);
  EXPECT_EQ(read_all(*b), "01234567");
  EXPECT_EQ(a->write(bytes("89")).bytes, 2u);
  EXPECT_EQ(read_all(*b), "89");
}

TEST(BytePipe, UnpluggedReadsAndWritesClosed) {
  auto [a, b] = make_byte_pipe("a", "b");
  a->write(bytes("lost"));
  b->unplug();
  EXPECT_FALSE(a->connected());
  EXPECT_FALSE(a->reopen());
  EXPECT_STREQ(a->loss_reason(), "unplugged");
  std::uint8_t buf[8];
  EXPECT_TRUE(a->read(buf).closed);
  EXPECT_TRUE(b->read(buf).closed);
  EXPECT_TRUE(a->write(bytes("x")).closed);
  a->plug_in();
  EXPECT_TRUE(b->connected());
  EXPECT_EQ(b->read(buf).bytes, 0u) << "bytes in flight were dropped";
}

// The PtuPort serves the emulator over the pipe exactly as over its pty.
TEST(BytePipe, TheEmulatorAnswersOverIt) {
  PtuEmulator emu;
  auto [host, unit] = make_byte_pipe("host", "unit");
  PtuPort port(emu, std::move(unit));
  host->write(bytes("ED\rFT\rPP\r"));
  port.service();
  EXPECT_EQ(read_all(*host), "ED *\r\n*\r\n* 0\r\n");
}

}  // namespace
}  // namespace robuter::hal
