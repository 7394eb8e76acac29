// SPDX-License-Identifier: GPL-3.0-or-later
// The script interpreter. Directives:
//   ! raw HEX..           send bytes given in hex, no terminator added
//   ! repeat N TEXT       send TEXT N times, no terminator
//   ! random N SEED       send N pseudo-random bytes (xorshift64*, seeded)
//   ! drain [MS]          read and discard until the link is quiet for MS (300) ms
//   ! silence MS          expect no reply for MS ms
//   ! sleep MS            wait
//   ! timeout MS          time allowed for each expected reply (default 3000)
//   ! until MS            the next `>` line is sent again every 100 ms until the reply matches
//                         its `<` expectation, for at most MS ms (a state the robot reaches in
//                         its own time, whatever the machine's load)
//   ! pipeline N L=P|L=P  write N lines at once, cycling through L, and expect the N replies
//                         in order, each matching its P
// An expectation not starting with `@` skips status-stream lines; `< @ …` expects one.
#include "tools/robuterctl/script.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "tools/robuterctl/pairing.hpp"
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

}  // namespace

ScriptResult run_script(Client& client, const std::string& path, std::FILE* out, const ScriptOptions& options) {
  ScriptResult r;
  std::ifstream in(path);
  if (!in) {
    fmt::print(out, "{}: cannot open: {}\n", path, std::strerror(errno));
    r.failures = 1;
    return r;
  }
  milliseconds timeout{3000};
  std::string raw;
  int lineno = 0;
  auto fail = [&](const std::string& what) {
    fmt::print(out, "{}:{}: FAIL {}\n", path, lineno, what);
    client.note(fmt::format("{}:{}: FAIL {}", path, lineno, what));
    ++r.failures;
  };
  // Whether to stop after a failure.
  auto stop_here = [&] { return !options.keep_going || interrupted(); };
  // Reads the next reply and matches it with `pat_text`; a failure is reported only when `report`
  // (an `until`'s tries before its last are silent).
  auto expect = [&](const std::string& pat_text, bool report = true) -> bool {
    Pattern pat(pat_text);
    if (pat.error()) {
      fail("bad pattern: " + *pat.error());
      return false;
    }
    const bool want_stream = !pat_text.empty() && pat_text[0] == '@';
    std::optional<std::string> got;
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
      const auto left = std::chrono::duration_cast<milliseconds>(deadline - std::chrono::steady_clock::now());
      got = client.read_line(std::max(left, milliseconds(0)));
      if (!got || want_stream || (*got)[0] != '@') break;  // a stream line is never a reply
    }
    if (interrupted()) {
      r.interrupted = true;
      fail("interrupted (Ctrl-C)");
      return false;
    }
    if (!got) {
      if (report) fail(fmt::format("expected '{}', got no reply within {} ms", pat_text, timeout.count()));
      return false;
    }
    if (!pat.matches(*got)) {
      if (report) fail(fmt::format("expected '{}', got '{}'", pat_text, visible(*got)));
      return false;
    }
    ++r.checks;
    return true;
  };
  milliseconds until{0};  // `! until MS` armed for the next exchange (0: none)
  std::string resend;     // the line an armed `until` sends again (empty: none yet)
  constexpr milliseconds kUntilGap{100};  // between an `until`'s tries
  while (std::getline(in, raw)) {
    ++lineno;
    const std::string line = trim(raw);
    if (line.empty() || line[0] == '#') continue;
    const char kind = line[0];
    const std::string rest = line.size() > 2 ? line.substr(2) : "";
    if (interrupted()) {
      r.interrupted = true;
      fail("interrupted (Ctrl-C)");
      return r;
    }
    if (kind == '>') {
      if (!client.send_line(rest)) return fail("link closed while sending"), r;
      if (until.count() > 0) resend = rest;
    } else if (kind == '<') {
      // An armed `until` is spent on this expectation; it retries when its line was sent.
      const bool retry = until.count() > 0 && !resend.empty();
      const auto end = std::chrono::steady_clock::now() + until;
      until = milliseconds(0);
      bool ok = expect(rest, !retry);
      while (retry && !ok && !interrupted() && std::chrono::steady_clock::now() + kUntilGap < end) {
        client.idle(kUntilGap);
        if (!client.send_line(resend)) return fail("link closed while sending"), r;
        ok = expect(rest, false);
      }
      if (retry && !ok) {  // the last try reports what came
        if (!client.send_line(resend)) return fail("link closed while sending"), r;
        ok = expect(rest);
      }
      resend.clear();
      if (!ok && stop_here()) return r;
    } else if (kind == '!') {
      std::istringstream ss(rest);
      std::string verb;
      ss >> verb;
      // The directive's MS argument, `fallback` when the line has none.
      auto ms_arg = [&ss](int fallback) {
        int ms = fallback;
        ss >> ms;
        return milliseconds(ms);
      };
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
        client.drain(ms_arg(300));
      } else if (verb == "silence") {
        if (const auto got = client.read_line(ms_arg(300))) {
          fail("expected silence, got '" + visible(*got) + "'");
          if (stop_here()) return r;
        } else {
          ++r.checks;
        }
      } else if (verb == "sleep") {
        client.idle(ms_arg(0));
      } else if (verb == "timeout") {
        timeout = ms_arg(3000);
      } else if (verb == "until") {
        until = ms_arg(3000);
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
        if (!ok && stop_here()) return r;
      } else {
        return fail("unknown directive '" + verb + "'"), r;
      }
    } else {
      return fail("a script line starts with '>', '<', '!' or '#'"), r;
    }
  }
  return r;
}

std::string leave_stopped(Client& client) {
  // Checksums may have been left on by the script: try plain lines, then with checksums.
  std::string report;
  for (const char* line : {"AM 0 0", "ASF"}) {
    std::string got;
    for (int attempt = 0; attempt < 2; ++attempt) {
      const std::string sent = attempt ? with_checksum(line) : std::string(line);
      if (!client.send_line(sent)) return "the link is closed (robuterd ended, or the port went away): nothing sent";
      std::optional<std::string> reply;
      const auto deadline = std::chrono::steady_clock::now() + milliseconds(2000);
      for (;;) {
        const auto left = std::chrono::duration_cast<milliseconds>(deadline - std::chrono::steady_clock::now());
        reply = client.read_line(std::max(left, milliseconds(0)));
        if (!reply || (*reply)[0] != '@') break;
      }
      got = reply ? *reply : "no reply";
      if (got.rfind("ack", 0) == 0) break;
    }
    report += fmt::format("{}{} → {}", report.empty() ? "" : ", ", line, got);
  }
  return report;
}

}  // namespace robuter::ctl
