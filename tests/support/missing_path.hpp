// Paths that cannot exist or cannot be written, made in a private temporary folder (never a fixed
// global path that another program or user could create).
#pragma once

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace robuter::test {

// A private folder, removed with the object: missing(name) is a path in a folder that does not
// exist there; under_file(name) a path whose parent is a regular file (no write succeeds, not even
// as root).
class MissingPaths {
 public:
  MissingPaths() {
    std::string t = (std::filesystem::temp_directory_path() / "robuter-missing-XXXXXX").string();
    if (::mkdtemp(t.data())) dir_ = t;
    std::ofstream(dir_ + "/file") << "a regular file\n";
  }
  ~MissingPaths() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  MissingPaths(const MissingPaths&) = delete;
  MissingPaths& operator=(const MissingPaths&) = delete;
  std::string missing(const std::string& name) const { return dir_ + "/missing/" + name; }
  std::string under_file(const std::string& name) const { return dir_ + "/file/" + name; }

 private:
  std::string dir_;  // the private folder
};

}  // namespace robuter::test
