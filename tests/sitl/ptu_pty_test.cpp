// SPDX-License-Identifier: GPL-3.0-or-later
// The pan-tilt emulator over a real pty: a client opens the slave like a serial port, sends the
// seed's commands and reads the unit's replies while the port (or the whole firmware) steps.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "hal/link/pty_link.hpp"
#include "hal/sitl/ptu_port.hpp"
#include "modules/firmware/firmware.hpp"

namespace robuter::hal {
namespace {

// A temporary folder removed at the end.
struct TempDir {
  std::string path;
  TempDir() {
    char tmpl[] = "/tmp/robuter-ptu-XXXXXX";
    path = ::mkdtemp(tmpl);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
};

// The client's end: the pty slave opened as a serial port would be (raw, non-blocking).
int open_client(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
  if (fd < 0) return fd;
  termios t{};
  tcgetattr(fd, &t);
  cfmakeraw(&t);
  tcsetattr(fd, TCSANOW, &t);
  return fd;
}

void write_all(int fd, const std::string& s) { ASSERT_EQ(::write(fd, s.data(), s.size()), static_cast<ssize_t>(s.size())); }

// Calls `step` until `lines` CR-LF-terminated lines have arrived on `fd` (at most `max_steps`).
template <typename Step>
std::string read_lines(int fd, int lines, int max_steps, Step step) {
  std::string got;
  for (int i = 0; i < max_steps; ++i) {
    step();
    char buf[256];
    ssize_t n;
    while ((n = ::read(fd, buf, sizeof buf)) > 0) got.append(buf, static_cast<std::size_t>(n));
    int seen = 0;
    for (std::size_t p = got.find("\r\n"); p != std::string::npos; p = got.find("\r\n", p + 2)) ++seen;
    if (seen >= lines) break;
  }
  return got;
}

TEST(PtuPty, PortAnswersAClientOnTheSlave) {
  TempDir dir;
  PtuEmulator unit;
  auto link = std::make_unique<PtyLink>(dir.path + "/ptu.pty");
  ASSERT_FALSE(link->error()) << *link->error();
  PtuPort port(unit, std::move(link));
  const int fd = open_client(dir.path + "/ptu.pty");
  ASSERT_GE(fd, 0);
  write_all(fd, "PP\r");
  EXPECT_EQ(read_lines(fd, 1, 50, [&] { port.service(); }), "PP * Current Pan position is 0\r\n");
  write_all(fd, "ED\rFT\rpp-12\rPP\r");
  EXPECT_EQ(read_lines(fd, 4, 50, [&] { port.service(); }), "ED *\r\n*\r\n*\r\n* 0\r\n");
  EXPECT_GT(port.bytes_in(), 0u);
  ::close(fd);
  for (int i = 0; i < 30; ++i) port.service();  // the client went away: nothing breaks
  EXPECT_FALSE(port.stream().connected());
}

// robuterd --sim --ptu-pty PATH: the seed's initialisation, then PP every 30 ms while the
// kernel steps on its virtual clock; the position advances at the commanded speed.
TEST(PtuPty, FirmwareServesTheUnitWhileStepping) {
  TempDir dir;
  FirmwareOptions opt;
  opt.sim = true;
  opt.speed = 0.0;
  opt.ptu_pty = dir.path + "/ptu.pty";
  Firmware fw(Config{}, opt);
  const auto err = fw.setup();
  ASSERT_FALSE(err) << *err;
  ASSERT_TRUE(fw.kernel().start());
  const int fd = open_client(opt.ptu_pty);
  ASSERT_GE(fd, 0);
  auto step = [&] { fw.kernel().step(); };
  write_all(fd, "ED\rFT\rI\rPA6000\rps1500\rpp1655\r");
  EXPECT_EQ(read_lines(fd, 6, 100, step), "ED *\r\n*\r\n*\r\n*\r\n*\r\n*\r\n");
  const double t0 = fw.sim()->time();
  int last = 0;
  for (int k = 0; k < 40; ++k) {  // 40 activations of 30 ms
    write_all(fd, "PP\r");
    std::string reply;
    for (int tick = 0; tick < 3; ++tick) reply += read_lines(fd, 0, 1, step);  // one 30 ms activation
    ASSERT_EQ(reply.substr(0, 2), "* ") << reply;
    const int p = std::atoi(reply.c_str() + 2);  // the seed's own parse
    EXPECT_GE(p, last);
    last = p;
  }
  const double t = fw.sim()->time() - t0;
  EXPECT_NEAR(t, 1.2, 0.05);
  // Motion started when pp1655 was served; ~1.2 s later: 187.5 (ramp) + 1500 × (t − 0.25).
  EXPECT_GE(last, 1200);
  EXPECT_LE(last, 1655);
  ::close(fd);
  fw.kernel().shutdown();
}

}  // namespace
}  // namespace robuter::hal
