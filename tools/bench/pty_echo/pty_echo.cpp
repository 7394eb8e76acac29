// SPDX-License-Identifier: GPL-3.0-or-later
// A bare pty that answers each CR-terminated line with one fixed reply: the floor of a pty round trip.
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <string>
#include <termios.h>
#include <unistd.h>

namespace {
volatile std::sig_atomic_t g_stop = 0;  // set by SIGINT/SIGTERM
void on_signal(int) { g_stop = 1; }
}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s LINK_PATH\n", argv[0]);
    return 2;
  }
  const std::string link = argv[1];
  const int master = posix_openpt(O_RDWR | O_NOCTTY);
  if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0) {
    std::perror("robuter_pty_echo: posix_openpt");
    return 1;
  }
  const char* slave_name = ptsname(master);
  // Keep the slave open so a client's close does not hang the master up; raw like robuterd's.
  const int slave = open(slave_name, O_RDWR | O_NOCTTY);
  termios t{};
  if (slave < 0 || tcgetattr(slave, &t) != 0) {
    std::perror("robuter_pty_echo: slave");
    return 1;
  }
  cfmakeraw(&t);
  tcsetattr(slave, TCSANOW, &t);
  unlink(link.c_str());
  if (symlink(slave_name, link.c_str()) != 0) {
    std::perror("robuter_pty_echo: symlink");
    return 1;
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  static constexpr char kReply[] = "S 0 0 0 0 0\r";  // the size of a BO reply
  char buf[4096];
  while (!g_stop) {
    pollfd p{master, POLLIN, 0};
    if (poll(&p, 1, 200) <= 0) continue;
    const ssize_t n = read(master, buf, sizeof buf);
    if (n <= 0) {
      if (n < 0 && errno != EINTR && errno != EAGAIN && errno != EIO) break;
      continue;
    }
    for (ssize_t i = 0; i < n; ++i)
      if (buf[i] == '\r' && write(master, kReply, sizeof kReply - 1) < 0) break;
  }
  unlink(link.c_str());
  return 0;
}
