// SPDX-License-Identifier: GPL-3.0-or-later
// Pty creation in raw mode, the client's symbolic link and its lock, client sessions (inotify).
#include "hal/link/pty_link.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/file.h>
#include <sys/inotify.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace robuter::hal {

namespace {
// The pid written in a lock file, or 0 (for the refusal message only).
long lock_owner(int fd) {
  char buf[32] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  return n > 0 ? std::strtol(buf, nullptr, 10) : 0;
}
}  // namespace

PtyLink::PtyLink(std::string path, Mode mode)
    : path_(std::move(path)), label_("pty " + path_), lock_path_(path_ + ".lock"), mode_(mode) {
  if (mode_ == Mode::sessions && !lock_path()) return;
  const int m = posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
  if (m < 0 || grantpt(m) != 0 || unlockpt(m) != 0) {
    error_ = std::string("cannot create a pty: ") + std::strerror(errno);
    if (m >= 0) ::close(m);
    return;
  }
  fcntl(m, F_SETFD, FD_CLOEXEC);
  slave_ = ptsname(m);
  in_fd_ = out_fd_ = m;
  // Raw, 8-bit, no echo, no CR/LF translation, set on the slave side through the master.
  make_raw();
  if (mode_ == Mode::sessions && !watch_clients()) {
    ::close(m);
    in_fd_ = out_fd_ = -1;
    return;
  }
  struct stat st {};
  if (lstat(path_.c_str(), &st) == 0) {
    if (!S_ISLNK(st.st_mode)) {
      error_ = "cannot link " + path_ + ": it exists and is not a symbolic link";
      ::close(m);
      in_fd_ = out_fd_ = -1;
      return;
    }
    ::unlink(path_.c_str());  // a stale link (a killed server's): ours now, under the lock
  }
  if (symlink(slave_.c_str(), path_.c_str()) != 0) {
    error_ = "cannot link " + path_ + ": " + std::strerror(errno);
    ::close(m);
    in_fd_ = out_fd_ = -1;
    return;
  }
  reopen();
}

PtyLink::~PtyLink() {
  if (in_fd_ >= 0) {
    ::unlink(path_.c_str());
    ::close(in_fd_);
  }
  if (inotify_fd_ >= 0) ::close(inotify_fd_);
  if (slave_fd_ >= 0) ::close(slave_fd_);
  // Unlinked while still locked: a server waiting for the lock then finds its file gone and
  // creates a new one (lock_path() checks the inode), so two never both hold it.
  if (lock_fd_ >= 0) {
    ::unlink(lock_path_.c_str());
    ::close(lock_fd_);
  }
}

// flock is released by the kernel when the process dies, however it dies: a killed server
// leaves at most an unlocked file, which the next one takes over.
bool PtyLink::lock_path() {
  for (int attempt = 0; attempt < 4; ++attempt) {
    const int fd = ::open(lock_path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0) {
      error_ = "cannot create the lock file " + lock_path_ + ": " + std::strerror(errno);
      return false;
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      const long pid = lock_owner(fd);
      ::close(fd);
      if (err == EWOULDBLOCK)
        error_ = path_ + " is in use by another robuterd" + (pid > 0 ? " (pid " + std::to_string(pid) + ")" : "") +
                 " (lock " + lock_path_ + " held)";
      else
        error_ = "cannot lock " + lock_path_ + ": " + std::strerror(err);
      return false;
    }
    struct stat held {}, named {};
    if (::fstat(fd, &held) == 0 && ::stat(lock_path_.c_str(), &named) == 0 && held.st_dev == named.st_dev &&
        held.st_ino == named.st_ino) {
      char pid[24];
      const int n = std::snprintf(pid, sizeof pid, "%ld\n", static_cast<long>(::getpid()));
      if (::ftruncate(fd, 0) == 0 && n > 0) (void)!::pwrite(fd, pid, static_cast<std::size_t>(n), 0);
      lock_fd_ = fd;
      return true;
    }
    ::close(fd);  // its owner removed it between our open and our lock: take the new one
  }
  error_ = "cannot lock " + lock_path_ + ": it keeps being replaced";
  return false;
}

// The server's own slave descriptor keeps the pty from hanging up when a client closes, so the
// bytes of a client that opened, wrote and closed between two activations are still read.
bool PtyLink::watch_clients() {
  slave_fd_ = ::open(slave_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (slave_fd_ < 0) {
    error_ = "cannot open the pty slave " + slave_ + ": " + std::strerror(errno);
    return false;
  }
  inotify_fd_ = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (inotify_fd_ < 0 || inotify_add_watch(inotify_fd_, slave_.c_str(), IN_OPEN | IN_CLOSE) < 0) {
    error_ = "cannot watch the clients of " + slave_ + " (inotify): " + std::strerror(errno) +
             " — raise fs.inotify.max_user_instances / max_user_watches";
    return false;
  }
  connected_ = true;
  return true;
}

void PtyLink::make_raw() {
  termios t{};
  if (tcgetattr(in_fd_, &t) != 0) return;
  termios raw = t;
  cfmakeraw(&raw);
  if (std::memcmp(&raw, &t, sizeof t) != 0) tcsetattr(in_fd_, TCSANOW, &raw);
}

bool PtyLink::reopen() {
  if (in_fd_ < 0) return false;
  if (mode_ == Mode::sessions) return connected_;
  pollfd p{in_fd_, POLLIN, 0};
  const int n = ::poll(&p, 1, 0);
  // The master reports POLLHUP while no client holds the slave open.
  connected_ = n >= 0 && !(p.revents & POLLHUP);
  if (connected_) {
    // A client that opened the slave may have reset the line discipline: raw again.
    termios t{};
    if (tcgetattr(in_fd_, &t) == 0 && (t.c_lflag & (ICANON | ECHO))) make_raw();
  }
  return connected_;
}

// Counts opens and closes of the slave by others (ours was open before the watch): the first
// open starts a session, the close of the last client ends it. No allocation: a fixed buffer.
ClientEvent PtyLink::next_client_event() {
  if (inotify_fd_ < 0) return ClientEvent::none;
  for (;;) {
    if (events_pos_ >= events_len_) {
      const ssize_t n = ::read(inotify_fd_, events_.data(), events_.size());
      if (n <= 0) return ClientEvent::none;
      events_len_ = static_cast<std::size_t>(n);
      events_pos_ = 0;
    }
    inotify_event e;
    if (events_len_ - events_pos_ < sizeof e) {
      events_pos_ = events_len_;
      continue;
    }
    std::memcpy(&e, events_.data() + events_pos_, sizeof e);
    events_pos_ += sizeof e + e.len;
    if (e.mask & IN_OPEN) {
      if (++clients_ == 1) {
        make_raw();  // a client (stty, a terminal program) may have changed the line
        return ClientEvent::session_start;
      }
      if (clients_ == 2) return ClientEvent::shared;
    } else if (e.mask & IN_CLOSE) {
      if (clients_ > 0 && --clients_ == 0) return ClientEvent::session_end;
    }
  }
}

void PtyLink::discard_unread_output() {
  if (slave_fd_ >= 0) tcflush(slave_fd_, TCIFLUSH);
}

}  // namespace robuter::hal
