// SPDX-License-Identifier: GPL-3.0-or-later
// A private temporary folder for a test's output files, removed with the object (no fixed global path).
#pragma once

#include <stdlib.h>

#include <filesystem>
#include <string>

namespace robuter::test {

// Made with mkdtemp under the system's temporary folder; `file(name)` is a path inside it.
class TempDir {
 public:
  TempDir() {
    std::string t = (std::filesystem::temp_directory_path() / "robuter-test-XXXXXX").string();
    if (::mkdtemp(t.data())) dir_ = t;
  }
  ~TempDir() {
    std::error_code ec;
    if (!dir_.empty()) std::filesystem::remove_all(dir_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  bool ok() const { return !dir_.empty(); }
  std::string file(const std::string& name) const { return dir_ + "/" + name; }

 private:
  std::string dir_;  // the folder ("" if it could not be made)
};

}  // namespace robuter::test
