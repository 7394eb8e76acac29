// SPDX-License-Identifier: GPL-3.0-or-later
// Field-by-field decoding of replies (units from docs/PROTOCOL.md).
#include "tools/robuterctl/decode.hpp"

#include <fmt/format.h>

#include <sstream>
#include <vector>

#include "protocol/codec/vocabulary.hpp"

namespace robuter::ctl {

namespace {
std::vector<std::string> split(const std::string& s, char sep = ' ') {
  std::vector<std::string> out;
  std::string w;
  std::istringstream in(s);
  if (sep == ' ') {
    while (in >> w) out.push_back(w);
  } else {
    while (std::getline(in, w, sep)) out.push_back(w);
  }
  return out;
}
long long num(const std::string& s) { return std::atoll(s.c_str()); }
std::string clock_text(const std::string& s) { return fmt::format("clock {} ticks ({:.2f} s)", s, static_cast<double>(num(s)) / 100.0); }
std::string posture_text(const std::string& x, const std::string& y, const std::string& t) {
  return fmt::format("x {:.1f} mm  y {:.1f} mm  theta {:.2f} deg", static_cast<double>(num(x)) / 10.0,
                     static_cast<double>(num(y)) / 10.0, static_cast<double>(num(t)) / 100.0);
}
std::string ranges_text(const std::vector<std::string>& f, std::size_t from, std::size_t n, const char* label) {
  std::string out;
  for (std::size_t i = 0; i < n && from + i < f.size(); ++i) {
    out += fmt::format("{}{:>2}:{:>5} ", label, i + 1, f[from + i]);
    if (i % 6 == 5 && i + 1 < n) out += "\n  ";
  }
  return out;
}
std::string detectors(long long mask) {
  std::string out;
  if (mask & protocol::kDetectBumper) out += "bumper ";
  if (mask & protocol::kDetectUltrasonic) out += "ultrasonic ";
  if (mask & protocol::kDetectComm) out += "comm-loss ";
  if (out.empty()) return "none";
  out.pop_back();
  return out;
}
std::string mode(const std::string& state, const std::string& reason) {
  return reason == "none" ? state : state + " (" + reason + ")";
}
std::string head(const std::string& sent) {
  const auto b = sent.find_first_not_of(" ,");
  return b == std::string::npos ? "" : sent.substr(b, 2);
}
}  // namespace

std::string describe_reply(const std::string& sent, const std::string& reply) {
  const auto f = split(reply);
  if (f.empty()) return "";
  const std::string& h = f[0];
  const std::string c = head(sent);
  const std::size_t n = f.size();
  if (h == "error" && n > 1) return "";
  if (h == "error") return "refused (XB1 for the reason)";
  if (h == "ack") return "";
  if (h == "S" && n == 6)
    return fmt::format("posture  {}  servo {}  {}", posture_text(f[1], f[2], f[3]), f[4] == "1" ? "on" : "off", clock_text(f[5]));
  if (h == "S" && n == 2) return fmt::format("mean read time {} ticks ({} ms)", f[1], num(f[1]) * 10);
  if (h == "C" && n == 2) return clock_text(f[1]);
  if (h == "T" && n == 2) return fmt::format("ultrasonic time-out {} ms", f[1]);
  if (h == "N" && n == 2) return fmt::format("node firing delay {} ticks ({} ms)", f[1], num(f[1]) * 10);
  if (h == "U" && n == 27)
    return fmt::format("ranges, mm (0 = inactive or not read yet)\n  {}\n  servo {}  {}", ranges_text(f, 1, 24, "s"),
                       f[25] == "1" ? "on" : "off", clock_text(f[26]));
  if (h == "V" && n == 30)
    return fmt::format("posture  {}  servo {}\n  {}\n  {}", posture_text(f[1], f[2], f[3]), f[4] == "1" ? "on" : "off",
                       ranges_text(f, 5, 24, "s"), clock_text(f[29]));
  if ((h == "P" || h == "F" || h == "D") && n == 74)
    return fmt::format("pan-tilt {} by 5 deg sector, mm\n  {}\n  {}",
                       h == "P" ? "ranges" : h == "F" ? "filtered ranges" : "differences", ranges_text(f, 1, 72, "#"),
                       clock_text(f[73]));
  if (h == "E" && n >= 6) {
    std::string out = fmt::format("emergency: {}{}cause {}  detectors {}  {}", f[2] == "1" ? "LATCHED  " : "",
                                  f[1] == "1" ? "HELD (waiting for sensor data)  " : "", f[3], detectors(num(f[4])),
                                  clock_text(f[5]));
    if (n >= 9)
      out += fmt::format("\n  speed granted {}%  rule {}{}", f[6], f[7], f[8] == "1" ? "  PROTECTIVE STOP (obstacle evidence ahead)" : "");
    return out;
  }
  if (h == "K" && n >= 5 && c == "XK") {
    const auto procs = static_cast<std::size_t>(num(f[4]));
    std::string out = fmt::format("kernel: {} ticks  tick lateness max {} us, p99 {} us\n  {:<12} {:>10} {:>8} {:>6} {:>8} {:>8}",
                                  f[1], f[2], f[3], "process", "runs", "overruns", "slips", "mean us", "max us");
    for (std::size_t i = 0; i < procs && 5 + 6 * i + 5 < n; ++i) {
      const std::size_t b = 5 + 6 * i;
      out += fmt::format("\n  {:<12} {:>10} {:>8} {:>6} {:>8} {:>8}", f[b], f[b + 1], f[b + 2], f[b + 3], f[b + 4], f[b + 5]);
    }
    out += "\n  " + clock_text(f[n - 1]);
    return out;
  }
  if (h == "D" && c == "XD" && n >= 11) {
    std::string out = fmt::format("pan-tilt {}  gate {}  doors {}\n  sweeps {}  passage width {} mm  last crossing {} ticks",
                                  mode(f[1], f[2]), mode(f[3], f[4]), mode(f[5], f[6]), f[7], f[8], f[9]);
    if (n >= 15) out += fmt::format("\n  demonstration {}  phase {}  laps {}", mode(f[10], f[11]), f[12], f[13]);
    out += "  " + clock_text(f[n - 1]);
    return out;
  }
  if (h == "V" && c == "XV" && n >= 2) {
    std::string out = fmt::format("firmware {} {}", f[1], n > 2 ? f[2] : "");
    for (std::size_t i = 3; i + 1 < n; i += 2) {
      if (f[i] == "proto") out += "  protocol revision " + f[i + 1];
      if (f[i] == "caps") {
        std::string caps = f[i + 1];
        for (auto& ch : caps)
          if (ch == ',') ch = ' ';
        out += "\n  capabilities: " + caps;
      }
    }
    return out;
  }
  if (h == "P" && c == "XP" && n >= 10) {
    return fmt::format("planner {}  goal x {:.1f} mm y {:.1f} mm\n  path {} mm (following {} mm)  replans {}  scans {}  plan {} us  longest run {} us  {}",
                       f[1], static_cast<double>(num(f[2])) / 10.0, static_cast<double>(num(f[3])) / 10.0, f[4], f[5], f[6],
                       f[7], f[8], f[9], n > 10 ? clock_text(f[10]) : "");
  }
  if (h == "M" && c == "XM" && n >= 6) {
    // Split after the sixth space: the rows may begin with spaces (free cells).
    std::size_t pos = 0;
    for (int i = 0; i < 6 && pos != std::string::npos; ++i) pos = reply.find(' ', pos + (i ? 1 : 0));
    const std::string rows = pos == std::string::npos ? "" : reply.substr(pos + 1);
    std::string out = fmt::format("map {} x {} cells of {} mm around x {:.1f} mm y {:.1f} mm (. unknown  # obstacle  P robot)",
                                  f[1], f[2], f[3], static_cast<double>(num(f[4])) / 10.0, static_cast<double>(num(f[5])) / 10.0);
    for (const auto& row : split(rows, '|')) out += "\n  |" + row + "|";
    return out;
  }
  return "";
}

EmergencyView read_xe(const std::string& xe_reply) {
  const auto f = split(xe_reply);
  EmergencyView v;
  if (f.size() < 6 || f[0] != "E") return v;
  v.valid = true;
  v.held = f[1] == "1";
  v.latched = f[2] == "1";
  v.cause = f[3];
  v.protective = f.size() >= 9 && f[8] == "1";
  return v;
}

EmergencyView read_stream(const std::string& at_line) {
  const auto f = split(at_line);
  EmergencyView v;
  if (f.size() < 9 || f[0] != "@") return v;
  v.valid = true;
  const long long e = num(f[7]);
  v.held = (e & 1) != 0;
  v.latched = (e & 2) != 0;
  v.protective = (e & 4) != 0;
  return v;
}

std::string protective_banner() {
  return "*** PROTECTIVE STOP: an obstacle in the way — no XR needed; send the motion again once it is clear ***";
}

std::string emergency_banner(const std::string& cause) {
  return fmt::format("*** EMERGENCY LATCHED: {} — the robot is stopped; XR re-enables once the cause is gone ***", cause);
}

std::string describe_stream(const std::string& at_line) {
  const auto f = split(at_line);
  if (f.size() < 9 || f[0] != "@") return at_line;
  const long long e = num(f[7]);
  return fmt::format("{}  servo {}  wheels {} {} cm/s  {}  {}", posture_text(f[1], f[2], f[3]), f[4] == "1" ? "on" : "off",
                     f[5], f[6], (e & 2) ? "EMERGENCY LATCHED" : (e & 4) ? "protective stop" : (e & 1) ? "motion held" : "no emergency", clock_text(f[8]));
}

}  // namespace robuter::ctl
