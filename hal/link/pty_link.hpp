// A pseudo-terminal the server creates; PATH becomes a symbolic link to its slave side.
#pragma once

#include <optional>
#include <string>

#include "hal/link/fd_stream.hpp"

namespace robuter::hal {

class PtyLink final : public FdStream {
 public:
  // Creates the pty and the link at `path`; on failure error() says why.
  explicit PtyLink(std::string path);
  ~PtyLink() override;
  PtyLink(const PtyLink&) = delete;
  PtyLink& operator=(const PtyLink&) = delete;

  const char* name() const override { return label_.c_str(); }
  // A client is attached when the master no longer reports a hang-up.
  bool reopen() override;
  const std::optional<std::string>& error() const { return error_; }
  const std::string& slave_name() const { return slave_; }

 private:
  std::string path_;                  // the symbolic link clients open
  std::string slave_;                 // /dev/pts/N
  std::string label_;                 // "pty PATH"
  std::optional<std::string> error_;  // why creation failed
};

}  // namespace robuter::hal
