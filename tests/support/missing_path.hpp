// SPDX-License-Identifier: GPL-3.0-or-later
// Paths that cannot exist or cannot be written, made in a private temporary folder (never a fixed
// global path that another program or user could create).
#pragma once

#include <fstream>
#include <string>

#include "tests/support/temp_dir.hpp"

namespace robuter::test {

// A private folder (TempDir), removed with the object: missing(name) is a path in a folder that
// does not exist there; under_file(name) a path whose parent is a regular file (no write
// succeeds, not even as root).
class MissingPaths {
 public:
  MissingPaths() { std::ofstream(dir_.file("file")) << "a regular file\n"; }
  std::string missing(const std::string& name) const { return dir_.file("missing/" + name); }
  std::string under_file(const std::string& name) const { return dir_.file("file/" + name); }

 private:
  TempDir dir_;  // the private folder
};

}  // namespace robuter::test
