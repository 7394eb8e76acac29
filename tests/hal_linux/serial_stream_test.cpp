// SPDX-License-Identifier: GPL-3.0-or-later
// The serial device stream: line settings, bytes both ways, and the device lost (hang-up,
// node removed or replaced) and found again without re-creating the stream.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include "hal/linux/serial_settings.hpp"
#include "hal/linux/serial_stream.hpp"
#include "tests/hal_linux/fake_device.hpp"

namespace robuter {
namespace {

using hal::FlowControl;
using hal::Parity;
using hal::SerialSettings;
using hal::SerialStream;

// A temporary folder for the device link, removed at the end.
struct TempDir {
  std::string path;
  TempDir() {
    char tmpl[] = "/tmp/robuter-serial-XXXXXX";
    path = mkdtemp(tmpl);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

// Waits (bounded, ~10 s) for `pred`: the helper thread works on its own time.
template <typename Pred>
bool eventually(Pred pred) {
  for (int i = 0; i < 2000; ++i) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return pred();
}

std::string read_all(SerialStream& s) {
  std::string out;
  std::uint8_t buf[256];
  for (;;) {
    const auto r = s.read(buf);
    if (r.closed || r.bytes == 0) break;
    out.append(reinterpret_cast<const char*>(buf), r.bytes);
  }
  return out;
}

bool write_all(SerialStream& s, std::string_view text) {
  const auto r = s.write({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
  return !r.closed && r.bytes == text.size();
}

// Bytes both ways through the stream and the fake device.
void expect_talks(SerialStream& s, test::FakeSerialDevice& dev, const std::string& tag) {
  ASSERT_TRUE(dev.send("ping " + tag));
  std::string got;
  ASSERT_TRUE(eventually([&] { return (got += read_all(s)).size() >= 5 + tag.size(); })) << got;
  EXPECT_EQ(got, "ping " + tag);
  ASSERT_TRUE(write_all(s, "pong " + tag));
  std::string back;
  ASSERT_TRUE(eventually([&] { return (back += dev.receive()).size() >= 5 + tag.size(); })) << back;
  EXPECT_EQ(back, "pong " + tag);
}

SerialSettings fast_retry() {
  SerialSettings s;
  s.retry_ms = 10;
  return s;
}

TEST(SerialSettings, WordsParse) {
  EXPECT_EQ(from_word<Parity>("even"), Parity::even);
  EXPECT_EQ(from_word<Parity>("odd"), Parity::odd);
  EXPECT_EQ(from_word<Parity>("mark"), std::nullopt);
  EXPECT_EQ(from_word<FlowControl>("hardware"), FlowControl::hardware);
  EXPECT_EQ(from_word<FlowControl>("software"), FlowControl::software);
  EXPECT_EQ(from_word<FlowControl>("rts"), std::nullopt);
  EXPECT_TRUE(hal::valid_baud(9600));
  EXPECT_TRUE(hal::valid_baud(921600));
  EXPECT_FALSE(hal::valid_baud(9601));
}

TEST(SerialSettings, TermiosBits) {
  termios t{};
  SerialSettings s;
  ASSERT_TRUE(hal::encode_termios(s, t));  // 8N1, no flow control
  EXPECT_EQ(t.c_cflag & CSIZE, static_cast<tcflag_t>(CS8));
  EXPECT_EQ(t.c_cflag & (PARENB | CSTOPB | CRTSCTS), 0u);
  EXPECT_EQ(t.c_iflag & (IXON | IXOFF | INPCK), 0u);
  EXPECT_NE(t.c_cflag & CLOCAL, 0u);
  EXPECT_NE(t.c_cflag & CREAD, 0u);
  EXPECT_EQ(t.c_lflag & (ICANON | ECHO), 0u);
  EXPECT_EQ(t.c_cc[VMIN], 1);  // idle non-blocking reads say EAGAIN, not 0
  EXPECT_EQ(t.c_cc[VTIME], 0);
  EXPECT_EQ(cfgetospeed(&t), static_cast<speed_t>(B9600));

  s = {115200, Parity::odd, 2, FlowControl::hardware, 500};
  ASSERT_TRUE(hal::encode_termios(s, t));
  EXPECT_NE(t.c_cflag & PARENB, 0u);
  EXPECT_NE(t.c_cflag & PARODD, 0u);
  EXPECT_NE(t.c_iflag & INPCK, 0u);
  EXPECT_NE(t.c_cflag & CSTOPB, 0u);
  EXPECT_NE(t.c_cflag & CRTSCTS, 0u);
  EXPECT_EQ(cfgetispeed(&t), static_cast<speed_t>(B115200));

  s = {19200, Parity::even, 1, FlowControl::software, 500};
  ASSERT_TRUE(hal::encode_termios(s, t));  // the previous bits are cleared
  EXPECT_NE(t.c_cflag & PARENB, 0u);
  EXPECT_EQ(t.c_cflag & (PARODD | CSTOPB | CRTSCTS), 0u);
  EXPECT_EQ(t.c_iflag & (IXON | IXOFF), static_cast<tcflag_t>(IXON | IXOFF));

  s.baud = 12345;
  EXPECT_FALSE(hal::encode_termios(s, t));
}

// The settings reach the device (read back through a second descriptor on the slave).
TEST(SerialStream, AppliesTheSettingsToTheDevice) {
  TempDir dir;
  test::FakeSerialDevice dev(dir.path + "/dev");
  ASSERT_TRUE(dev.ok());
  SerialSettings s{38400, Parity::even, 2, FlowControl::none, 10};
  SerialStream stream(dir.path + "/dev", s, "serial test");
  ASSERT_FALSE(stream.error()) << *stream.error();
  const int fd = ::open(dev.slave().c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
  ASSERT_GE(fd, 0);
  termios t{};
  ASSERT_EQ(tcgetattr(fd, &t), 0);
  ::close(fd);
  EXPECT_EQ(cfgetospeed(&t), static_cast<speed_t>(B38400));
  // (a pty clears PARENB itself: pty_set_termios has no parity; TermiosBits covers it)
  EXPECT_NE(t.c_iflag & INPCK, 0u);
  EXPECT_NE(t.c_cflag & CSTOPB, 0u);
  EXPECT_EQ(t.c_lflag & ICANON, 0u);
  expect_talks(stream, dev, "a");
}

TEST(SerialStream, MissingDeviceAtStartUpIsAClearError) {
  SerialStream stream("/tmp/robuter-no-such-device", SerialSettings{}, "serial test");
  ASSERT_TRUE(stream.error());
  EXPECT_NE(stream.error()->find("/tmp/robuter-no-such-device"), std::string::npos) << *stream.error();
  EXPECT_NE(stream.error()->find("No such file"), std::string::npos) << *stream.error();
  EXPECT_FALSE(stream.connected());
  EXPECT_EQ(stream.fd(), -1);
}

TEST(SerialStream, NotATerminalIsRefused) {
  SerialStream stream("/dev/null", SerialSettings{}, "serial test");
  ASSERT_TRUE(stream.error());
  EXPECT_NE(stream.error()->find("/dev/null"), std::string::npos) << *stream.error();
}

TEST(SerialStream, UnsupportedRateIsRefused) {
  SerialSettings s;
  s.baud = 1234;
  SerialStream stream("/dev/null", s, "serial test");
  ASSERT_TRUE(stream.error());
  EXPECT_NE(stream.error()->find("1234"), std::string::npos) << *stream.error();
}

// Unplugged (master closed, link removed): lost with "hung up"; re-plugged at the same path:
// the same stream talks again.
TEST(SerialStream, ComesBackAfterTheDeviceHungUp) {
  TempDir dir;
  test::FakeSerialDevice dev(dir.path + "/dev");
  ASSERT_TRUE(dev.ok());
  SerialStream stream(dir.path + "/dev", fast_retry(), "serial test");
  ASSERT_FALSE(stream.error()) << *stream.error();
  expect_talks(stream, dev, "before");
  EXPECT_EQ(stream.loss_reason(), nullptr);

  dev.unplug();
  ASSERT_TRUE(eventually([&] {
    read_all(stream);
    return !stream.connected();
  }));
  EXPECT_STREQ(stream.loss_reason(), "hung up");
  EXPECT_EQ(stream.losses(), 1u);
  EXPECT_EQ(stream.fd(), -1);
  EXPECT_TRUE(eventually([&] { return stream.failed_attempts() >= 3; }));  // it keeps looking
  EXPECT_FALSE(stream.reopen());

  ASSERT_TRUE(dev.plug());
  ASSERT_TRUE(eventually([&] { return stream.reopen(); }));
  EXPECT_TRUE(stream.connected());
  EXPECT_GE(stream.fd(), 0);
  EXPECT_EQ(stream.reopens(), 1u);
  expect_talks(stream, dev, "after");
}

// A new device node at the path while the old one never hangs up (the old master stays
// open): the helper sees the path names another node; the stream moves to the new one.
TEST(SerialStream, FollowsANewNodeAtThePath) {
  TempDir dir;
  test::FakeSerialDevice dev(dir.path + "/dev");
  ASSERT_TRUE(dev.ok());
  SerialStream stream(dir.path + "/dev", fast_retry(), "serial test");
  ASSERT_FALSE(stream.error()) << *stream.error();
  expect_talks(stream, dev, "old");
  ASSERT_TRUE(dev.plug(/*keep_old=*/true));
  ASSERT_TRUE(eventually([&] {
    read_all(stream);
    return !stream.connected();
  }));
  EXPECT_STREQ(stream.loss_reason(), "device node removed or replaced");
  ASSERT_TRUE(eventually([&] { return stream.reopen(); }));
  expect_talks(stream, dev, "new");
  EXPECT_EQ(stream.losses(), 1u);
  EXPECT_EQ(stream.reopens(), 1u);
}

// Writing to a device that went away loses it too (no exception, no abort).
TEST(SerialStream, WriteToAGoneDeviceLosesIt) {
  TempDir dir;
  test::FakeSerialDevice dev(dir.path + "/dev");
  ASSERT_TRUE(dev.ok());
  SerialStream stream(dir.path + "/dev", fast_retry(), "serial test");
  ASSERT_FALSE(stream.error()) << *stream.error();
  dev.unplug();
  EXPECT_TRUE(eventually([&] {
    write_all(stream, "x");
    return !stream.connected();
  }));
  EXPECT_NE(stream.loss_reason(), nullptr);
}

}  // namespace
}  // namespace robuter
