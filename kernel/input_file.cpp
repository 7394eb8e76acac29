// SPDX-License-Identifier: GPL-3.0-or-later
// The checks before reading a given file: its type and size from the open descriptor (no race with a swap).
#include "kernel/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace robuter {

namespace {
const char* kind(mode_t m) {
  if (S_ISDIR(m)) return "a folder";
  if (S_ISCHR(m)) return "a character device";
  if (S_ISBLK(m)) return "a block device";
  if (S_ISFIFO(m)) return "a FIFO";
  if (S_ISSOCK(m)) return "a socket";
  return "not a regular file";
}
}  // namespace

std::optional<std::string> read_input_file(const std::string& path, std::string& out, std::size_t max_bytes) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer; a regular file ignores it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return std::string("cannot open: ") + std::strerror(errno);
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int err = errno;
    ::close(fd);
    return std::string("cannot open: ") + std::strerror(err);
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd);
    return S_ISDIR(st.st_mode) ? std::string("is a folder, not a file") : std::string("is ") + kind(st.st_mode) +
                                                                          ", not a regular file";
  }
  if (static_cast<unsigned long long>(st.st_size) > max_bytes) {
    ::close(fd);
    return "is larger than " + std::to_string(max_bytes / (1024 * 1024)) + " MB (" + std::to_string(st.st_size) +
           " bytes)";
  }
  out.assign(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t done = 0;
  while (done < out.size()) {
    const ssize_t n = ::read(fd, out.data() + done, out.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      return std::string("read error: ") + std::strerror(err);
    }
    if (n == 0) break;  // shorter than it was: take what is there
    done += static_cast<std::size_t>(n);
  }
  out.resize(done);
  ::close(fd);
  return std::nullopt;
}

}  // namespace robuter
