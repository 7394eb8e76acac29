// The script interpreter. Directives:
//   ! raw HEX..           send bytes given in hex, no terminator added
//   ! repeat N TEXT       send TEXT N times, no terminator
//   ! random N SEED       send N pseudo-random bytes (xorshift64*, seeded)
//   ! drain [MS]          read and discard until the link is quiet for MS (300) ms
//   ! silence MS          expect no reply for MS ms
//   ! sleep MS            wait
//   ! timeout MS          time allowed for each expected reply (default 3000)
//   ! pipeline N L=P|L=P  write N lines at once, cycling through L, and expect the N replies
//                         in order, each matching its P
#include "tools/robuterctl/script.hpp"

#include <fmt/format.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "tools/robuterctl/pattern.hpp"

namespace robuter::ctl {

namespace {

using std::chrono::milliseconds;

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::string visible(const std::string& s) {
  std::string out;
  for (unsigned char c : s) out += (c >= 32 && c < 127) ? std::string(1, static_cast<char>(c)) : fmt::format("\\x{:02x}", c);
  return out;
}

}  // namespace

ScriptResult run_script(Client& client, const std::string& path, std::FILE* out) {
  ScriptResult r;
  std::ifstream in(path);
  if (!in) {
    fmt::print(out, "{}: cannot open\n", path);
    r.failures = 1;
    return r;
  }
  milliseconds timeout{3000};
  std::string raw;
  int lineno = 0;
  auto fail = [&](const std::string& what) {
    fmt::print(out, "{}:{}: FAIL {}\n", path, lineno, what);
    ++r.failures;
  };
  auto expect = [&](const std::string& pat_text) -> bool {
    Pattern pat(pat_text);
    if (pat.error()) {
      fail("bad pattern: " + *pat.error());
      return false;
    }
    const auto got = client.read_line(timeout);
    if (!got) {
      fail(fmt::format("expected '{}', got no reply within {} ms", pat_text, timeout.count()));
      return false;
    }
    if (!pat.matches(*got)) {
      fail(fmt::format("expected '{}', got '{}'", pat_text, visible(*got)));
      return false;
    }
    ++r.checks;
    return true;
  };
  while (std::getline(in, raw)) {
    ++lineno;
    const std::string line = trim(raw);
    if (line.empty() || line[0] == '#') continue;
    const char kind = line[0];
    const std::string rest = line.size() > 2 ? line.substr(2) : "";
    if (kind == '>') {
      if (!client.send_line(rest)) return fail("link closed while sending"), r;
    } else if (kind == '<') {
      if (!expect(rest)) return r;
    } else if (kind == '!') {
      std::istringstream ss(rest);
      std::string verb;
      ss >> verb;
      if (verb == "raw") {
        std::string bytes, hex;
        while (ss >> hex) bytes += static_cast<char>(std::stoi(hex, nullptr, 16));
        client.send_raw(bytes);
      } else if (verb == "repeat") {
        std::size_t n = 0;
        std::string text;
        ss >> n >> text;
        std::string bytes;
        for (std::size_t i = 0; i < n; ++i) bytes += text;
        client.send_raw(bytes);
      } else if (verb == "random") {
        std::size_t n = 0;
        std::uint64_t seed = 1;
        ss >> n >> seed;
        std::string bytes(n, '\0');
        std::uint64_t x = seed ? seed : 1;
        for (auto& c : bytes) {
          x ^= x >> 12, x ^= x << 25, x ^= x >> 27;
          c = static_cast<char>((x * 0x2545F4914F6CDD1DULL) >> 56);
        }
        // Written in slices while replies are drained, as a real client would read them.
        std::thread writer([&] { client.send_raw(bytes); });
        while (client.read_line(milliseconds(500))) {
        }
        writer.join();
      } else if (verb == "drain") {
        int ms = 300;
        ss >> ms;
        client.drain(milliseconds(ms));
      } else if (verb == "silence") {
        int ms = 300;
        ss >> ms;
        if (const auto got = client.read_line(milliseconds(ms))) return fail("expected silence, got '" + visible(*got) + "'"), r;
        ++r.checks;
      } else if (verb == "sleep") {
        int ms = 0;
        ss >> ms;
        std::this_thread::sleep_for(milliseconds(ms));
      } else if (verb == "timeout") {
        int ms = 3000;
        ss >> ms;
        timeout = milliseconds(ms);
      } else if (verb == "pipeline") {
        std::size_t n = 0;
        ss >> n;
        std::string spec;
        std::getline(ss, spec);
        std::vector<std::pair<std::string, std::string>> items;
        std::istringstream parts(spec);
        std::string part;
        while (std::getline(parts, part, '|')) {
          part = trim(part);
          const auto eq = part.find('=');
          if (eq == std::string::npos) return fail("pipeline item needs LINE=PATTERN: " + part), r;
          items.emplace_back(part.substr(0, eq), part.substr(eq + 1));
        }
        if (items.empty() || n == 0) return fail("pipeline needs a count and items"), r;
        std::string bytes;
        for (std::size_t i = 0; i < n; ++i) bytes += items[i % items.size()].first + "\r";
        std::thread writer([&] { client.send_raw(bytes); });
        bool ok = true;
        for (std::size_t i = 0; i < n && ok; ++i) ok = expect(items[i % items.size()].second);
        writer.join();
        if (!ok) return r;
      } else {
        return fail("unknown directive '" + verb + "'"), r;
      }
    } else {
      return fail("a script line starts with '>', '<', '!' or '#'"), r;
    }
  }
  return r;
}

}  // namespace robuter::ctl
