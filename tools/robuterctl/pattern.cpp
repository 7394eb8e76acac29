// SPDX-License-Identifier: GPL-3.0-or-later
// Pattern compilation to std::regex, with integer ranges checked on the captures.
#include "tools/robuterctl/pattern.hpp"

#include <cstdlib>

namespace robuter::ctl {

namespace {
std::string escape(const std::string& s) {
  static const std::string special = R"(\^$.|?*+()[]{})";
  std::string out;
  for (char c : s) {
    if (special.find(c) != std::string::npos) out += '\\';
    out += c;
  }
  return out;
}
}  // namespace

Pattern::Pattern(const std::string& text) : text_(text) {
  std::string re;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t open = text.find('{', i);
    if (open == std::string::npos) {
      re += escape(text.substr(i));
      break;
    }
    re += escape(text.substr(i, open - i));
    const std::size_t close = text.find('}', open);
    if (close == std::string::npos) {
      error_ = "unclosed '{' in pattern";
      return;
    }
    const std::string tok = text.substr(open + 1, close - open - 1);
    if (tok == "int") {
      re += "(-?[0-9]+)";
      groups_.emplace_back();
    } else if (tok.rfind("int:", 0) == 0) {
      const auto dots = tok.find("..");
      if (dots == std::string::npos) {
        error_ = "expected {int:LO..HI}";
        return;
      }
      re += "(-?[0-9]+)";
      groups_.push_back(Range{std::atoll(tok.substr(4, dots - 4).c_str()), std::atoll(tok.substr(dots + 2).c_str())});
    } else if (tok.rfind("ints:", 0) == 0) {
      const int n = std::atoi(tok.substr(5).c_str());
      if (n <= 0) {
        error_ = "expected {ints:N} with N > 0";
        return;
      }
      re += "-?[0-9]+(?: -?[0-9]+){" + std::to_string(n - 1) + "}";
    } else if (tok == "word") {
      re += "[^ ]+";
    } else if (tok == "any") {
      re += ".*";
    } else {
      error_ = "unknown placeholder {" + tok + "}";
      return;
    }
    i = close + 1;
  }
  re_ = std::regex(re);
}

bool Pattern::matches(const std::string& line) const {
  if (error_) return false;
  std::smatch m;
  if (!std::regex_match(line, m, re_)) return false;
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    if (!groups_[g]) continue;
    const long long v = std::atoll(m[static_cast<int>(g + 1)].str().c_str());
    if (v < groups_[g]->lo || v > groups_[g]->hi) return false;
  }
  return true;
}

}  // namespace robuter::ctl
