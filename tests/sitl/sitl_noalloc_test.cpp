// SPDX-License-Identifier: GPL-3.0-or-later
// Proves the pan-tilt paths allocate nothing after start-up: the emulator's protocol and motion,
// channel-7 firing, the built-in sweep and the pty service, inside the whole firmware.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "modules/firmware/firmware.hpp"
#include "tests/support/alloc_counter.hpp"

namespace robuter {
namespace {

TEST(SitlNoAlloc, TenThousandTicksWithThePanTiltAllocateNothing) {
  char tmpl[] = "/tmp/robuter-ptu-noalloc-XXXXXX";
  const std::string dir = ::mkdtemp(tmpl);
  FirmwareOptions opt;
  opt.sim = true;
  opt.speed = 0.0;
  opt.ptu_pty = dir + "/ptu.pty";
  opt.ptu_sweep = true;
  {
    Firmware fw(Config{}, opt);
    ASSERT_FALSE(fw.setup());
    ASSERT_TRUE(fw.kernel().start());
    const int fd = ::open(opt.ptu_pty.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    ASSERT_GE(fd, 0);
    termios t{};
    tcgetattr(fd, &t);
    cfmakeraw(&t);
    tcsetattr(fd, TCSANOW, &t);
    const char init[] = "ED\rFT\rPA6000\rps1500\rpp1655\rPS\rPA\rXX\rpp9999\r";
    ASSERT_GT(::write(fd, init, sizeof init - 1), 0);
    char buf[512];
    for (int i = 0; i < 200; ++i) {  // warm-up: every reply kind, a whole sweep started
      fw.kernel().step();
      while (::read(fd, buf, sizeof buf) > 0) {
      }
    }
    std::size_t replies = 0;
    test::AllocCounter counter;
    for (int i = 0; i < 10'000; ++i) {
      if (i % 3 == 0) {
        const char* cmd = (i % 300 == 0) ? "pp1655\rps1500\rBAD\r" : "PP\r";
        [[maybe_unused]] const auto n = ::write(fd, cmd, std::char_traits<char>::length(cmd));
      }
      fw.kernel().step();
      ssize_t n;
      while ((n = ::read(fd, buf, sizeof buf)) > 0)
        for (ssize_t k = 0; k < n; ++k) replies += buf[k] == '\n';
    }
    EXPECT_EQ(counter.count(), 0u);
    EXPECT_GE(replies, 3334u);
    EXPECT_GT(fw.sim()->last_pan_tilt().time_s, 90.0);  // the sweep kept firing channel 7
    ::close(fd);
    fw.kernel().shutdown();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace robuter
