// Pty creation in raw mode, the client's symbolic link, and re-attachment of a client.
#include "hal/link/pty_link.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace robuter::hal {

PtyLink::PtyLink(std::string path) : path_(std::move(path)), label_("pty " + path_) {
  const int m = posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
  if (m < 0 || grantpt(m) != 0 || unlockpt(m) != 0) {
    error_ = std::string("cannot create a pty: ") + std::strerror(errno);
    if (m >= 0) ::close(m);
    return;
  }
  fcntl(m, F_SETFD, FD_CLOEXEC);
  slave_ = ptsname(m);
  // Raw, 8-bit, no echo, no CR/LF translation, set on the slave side through the master.
  termios t{};
  if (tcgetattr(m, &t) == 0) {
    cfmakeraw(&t);
    tcsetattr(m, TCSANOW, &t);
  }
  struct stat st {};
  if (lstat(path_.c_str(), &st) == 0) {
    if (!S_ISLNK(st.st_mode)) {
      error_ = "cannot link " + path_ + ": it exists and is not a symbolic link";
      ::close(m);
      return;
    }
    ::unlink(path_.c_str());
  }
  if (symlink(slave_.c_str(), path_.c_str()) != 0) {
    error_ = "cannot link " + path_ + ": " + std::strerror(errno);
    ::close(m);
    return;
  }
  in_fd_ = out_fd_ = m;
  reopen();
}

PtyLink::~PtyLink() {
  if (in_fd_ >= 0) {
    ::unlink(path_.c_str());
    ::close(in_fd_);
  }
}

bool PtyLink::reopen() {
  if (in_fd_ < 0) return false;
  pollfd p{in_fd_, POLLIN, 0};
  const int n = ::poll(&p, 1, 0);
  // The master reports POLLHUP while no client holds the slave open.
  connected_ = n >= 0 && !(p.revents & POLLHUP);
  if (connected_) {
    // A client that opened the slave may have reset the line discipline: raw again.
    termios t{};
    if (tcgetattr(in_fd_, &t) == 0 && (t.c_lflag & (ICANON | ECHO))) {
      cfmakeraw(&t);
      tcsetattr(in_fd_, TCSANOW, &t);
    }
  }
  return connected_;
}

}  // namespace robuter::hal
