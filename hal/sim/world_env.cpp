// SPDX-License-Identifier: GPL-3.0-or-later
// Seed 000's environment-file loader: strict line structure, every error with its line.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "hal/sim/toml_fields.hpp"
#include "hal/sim/world_io.hpp"

namespace robuter::sim {

namespace {

using detail::ParseFailure;

// A non-blank line cut into whitespace-separated tokens.
struct Line {
  int number = 0;                      // 1-based line number
  std::vector<std::string_view> words; // its tokens
};

// Splits the text into non-blank lines of tokens (CR of CRLF files counts as blank).
std::vector<Line> split_lines(std::string_view text) {
  std::vector<Line> lines;
  int number = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    ++number;
    const std::string_view row = text.substr(pos, end - pos);
    Line line{number, {}};
    std::size_t i = 0;
    while (i < row.size()) {
      while (i < row.size() && std::isspace(static_cast<unsigned char>(row[i]))) ++i;
      std::size_t j = i;
      while (j < row.size() && !std::isspace(static_cast<unsigned char>(row[j]))) ++j;
      if (j > i) line.words.push_back(row.substr(i, j - i));
      i = j;
    }
    if (!line.words.empty()) lines.push_back(std::move(line));
    if (end == text.size()) break;
    pos = end + 1;
  }
  return lines;
}

// Reads tokens as the seed's fscanf would accept them, but refusing partial matches.
class EnvReader {
 public:
  EnvReader(std::string_view text, std::string_view file)
      : lines_(split_lines(text)), file_(file) {}

  [[noreturn]] void fail(int line, const std::string& message) const {
    throw ParseFailure{Error{file_, line, message}};
  }

  bool at_end() const { return next_ >= lines_.size(); }
  const Line& peek() const { return lines_[next_]; }
  const Line& take() { return lines_[next_++]; }
  const std::string& file() const { return file_; }

  // A count line: exactly one non-negative whole number.
  long count(const Line& line, const std::string& what) const {
    if (line.words.size() != 1) {
      fail(line.number, "expected " + what + " alone on the line, found " +
                            std::to_string(line.words.size()) + " values");
    }
    const std::string_view w = line.words[0];
    long v = 0;
    const auto [p, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || p != w.data() + w.size()) {
      fail(line.number, "expected " + what + " (a whole number), found '" + std::string(w) + "'");
    }
    if (v < 0) fail(line.number, "bad count: " + what + " cannot be negative (" + std::string(w) + ")");
    return v;
  }

  // A real number in metres; '+' signs allowed, NaN and infinities refused.
  double number(const Line& line, std::string_view w, const std::string& what) const {
    std::string_view s = w;
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    double v = 0.0;
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc() || p != s.data() + s.size() || !std::isfinite(v)) {
      fail(line.number, "expected a number for " + what + ", found '" + std::string(w) + "'");
    }
    return v;
  }

 private:
  std::vector<Line> lines_;  // non-blank lines
  std::size_t next_ = 0;     // next line to read
  std::string file_;         // file name for messages
};

// The grammar of annex 1, one element per line.
World read_env(std::string_view text, std::string_view file) {
  EnvReader in(text, file);
  World world;
  world.source = std::string(file);
  if (in.at_end()) return world;  // "may contain no information at all"
  const Line& head = in.take();
  const long obstacles = in.count(head, "the number of obstacles");
  for (long o = 1; o <= obstacles; ++o) {
    const std::string name = "obstacle " + std::to_string(o);
    if (in.at_end()) {
      in.fail(head.number, "bad count: the file declares " + std::to_string(obstacles) +
                               " obstacles but ends after " + std::to_string(o - 1));
    }
    const Line& cl = in.take();
    const long n = in.count(cl, "the vertex count of " + name);
    if (n < 2) {
      in.fail(cl.number, "bad count: " + name + " has " + std::to_string(n) +
                             " vertices (at least 2 are needed)");
    }
    Obstacle ob{name, {}, cl.number};
    for (long v = 1; v <= n; ++v) {
      if (in.at_end()) {
        in.fail(cl.number, "bad count: " + name + " declares " + std::to_string(n) +
                               " vertices but the file ends after " + std::to_string(v - 1));
      }
      const Line& vl = in.take();
      const std::string what = "vertex " + std::to_string(v) + " of " + name;
      if (vl.words.size() != 2) {
        if (vl.words.size() == 1) {
          in.fail(vl.number, "bad count: " + name + " declares " + std::to_string(n) +
                                 " vertices but line has a single value where " + what +
                                 " ('x y') was expected");
        }
        in.fail(vl.number, "expected 'x y' for " + what + ", found " +
                               std::to_string(vl.words.size()) + " values");
      }
      const Vec2 p(in.number(vl, vl.words[0], "x of " + what),
                   in.number(vl, vl.words[1], "y of " + what));
      if (!ob.vertices.empty() && ob.vertices.back() == p) continue;  // repeated vertex
      ob.vertices.push_back(p);
    }
    if (ob.vertices.size() > 2 && ob.vertices.front() == ob.vertices.back()) {
      ob.vertices.pop_back();  // explicitly closed: the closing edge is implied anyway
    }
    if (ob.vertices.size() < 2) in.fail(cl.number, name + " has no extent (all vertices equal)");
    world.add_obstacle(std::move(ob));
  }
  if (!in.at_end()) {
    in.fail(in.peek().number, "bad count: unexpected data after the last of the " +
                                  std::to_string(obstacles) + " declared obstacles");
  }
  return world;
}

}  // namespace

// Names the world after the file and builds its grid; errors become values here.
Result<World> parse_world_env(std::string_view text, std::string_view file) {
  try {
    World w = read_env(text, file);
    const std::string f(file);
    const auto slash = f.find_last_of('/');
    std::string stem = slash == std::string::npos ? f : f.substr(slash + 1);
    if (const auto dot = stem.find_last_of('.'); dot != std::string::npos) stem.resize(dot);
    w.name = stem;
    w.finalize();
    return w;
  } catch (const ParseFailure& e) {
    return e.error;
  }
}

}  // namespace robuter::sim
