// SPDX-License-Identifier: GPL-3.0-or-later
// The state file (state_file.hpp): text in, text out, a temporary file renamed over the old one.
#include "modules/localise/state_file.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "kernel/input_file.hpp"
#include "protocol/codec/limits.hpp"

namespace robuter::localise {

std::string state_text(const SavedPose& p) {
  return fmt::format("robuter-localise 1\n# robuterd's last map pose: x y (0.1 mm) theta (0.01 degree)\npose {} {} {}\n",
                     p.x, p.y, p.theta);
}

std::optional<SavedPose> read_state_file(const std::string& path, std::string& why) {
  std::string text;
  if (auto err = read_input_file(path, text, 64 * 1024)) {
    why = path + ": " + *err;
    return std::nullopt;
  }
  std::istringstream in(text);
  std::string line;
  int n = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++n;
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      if (line != "robuter-localise 1") {
        why = fmt::format("{}:{}: expected the header 'robuter-localise 1'", path, n);
        return std::nullopt;
      }
      header = true;
      continue;
    }
    std::istringstream words(line);
    std::string key, extra;
    long long x = 0, y = 0, t = 0;
    if (!(words >> key >> x >> y >> t) || key != "pose" || (words >> extra)) {
      why = fmt::format("{}:{}: expected 'pose <x> <y> <theta>' (integers)", path, n);
      return std::nullopt;
    }
    constexpr long long lo = INT32_MIN, hi = INT32_MAX;
    if (x < lo || x > hi || y < lo || y > hi || t < lo || t > hi || !protocol::heading_in_range(static_cast<std::int32_t>(t))) {
      why = fmt::format("{}:{}: a value is out of range (theta in (-18000, 18000])", path, n);
      return std::nullopt;
    }
    return SavedPose{static_cast<std::int32_t>(x), static_cast<std::int32_t>(y), static_cast<std::int32_t>(t)};
  }
  why = fmt::format("{}: {}", path, header ? "no 'pose' line" : "empty");
  return std::nullopt;
}

bool write_state_file(const std::string& path, const SavedPose& p, std::string& why) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      why = path + ": cannot write (" + tmp + ")";
      return false;
    }
    out << state_text(p);
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      why = path + ": write failed";
      return false;
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    why = path + ": cannot replace the file";
    return false;
  }
  return true;
}

void StateFileWriter::post(const SavedPose& p) {
  if (SavedPose* v = slot_.try_fill()) {
    *v = p;
    slot_.publish();
  }
}

bool StateFileWriter::drain() {
  const SavedPose* v = slot_.take();
  if (v == nullptr) return false;
  const SavedPose p = *v;
  slot_.release();
  std::string why;
  if (!write_state_file(path_, p, why)) {
    // Not the kernel's thread: a message on stderr costs the robot nothing.
    if (failed_.fetch_add(1) == 0) std::fprintf(stderr, "robuterd: localise state file: %s\n", why.c_str());
    return false;
  }
  written_.fetch_add(1);
  return true;
}

}  // namespace robuter::localise
