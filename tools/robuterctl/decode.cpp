// Field-by-field decoding of replies (units from docs/PROTOCOL.md).
#include "tools/robuterctl/decode.hpp"

#include <fmt/format.h>

#include <sstream>
#include <vector>

#include "protocol/codec/vocabulary.hpp"

namespace robuter::ctl {

namespace {
std::vector<std::string> split(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  std::string w;
  while (in >> w) out.push_back(w);
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
    if (i % 6 == 5) out += "\n  ";
  }
  return out;
}
}  // namespace

std::string describe_reply(const std::string& sent, const std::string& reply) {
  const auto f = split(reply);
  if (f.empty()) return reply;
  const std::string& h = f[0];
  if (h == "S" && f.size() == 6)
    return fmt::format("posture  {}  servo {}  {}", posture_text(f[1], f[2], f[3]), f[4] == "1" ? "on" : "off", clock_text(f[5]));
  if (h == "S" && f.size() == 2) return fmt::format("mean read time {} ticks ({} ms)", f[1], num(f[1]) * 10);
  if (h == "C" && f.size() == 2) return clock_text(f[1]);
  if (h == "T" && f.size() == 2) return fmt::format("ultrasonic time-out {} ms", f[1]);
  if (h == "N" && f.size() == 2) return fmt::format("node firing delay {} ticks ({} ms)", f[1], num(f[1]) * 10);
  if (h == "U" && f.size() == 27)
    return fmt::format("ranges, mm (0 = inactive or not read yet)\n  {}\n  servo {}  {}", ranges_text(f, 1, 24, "s"),
                       f[25] == "1" ? "on" : "off", clock_text(f[26]));
  if (h == "V" && f.size() == 30)
    return fmt::format("posture  {}  servo {}\n  {}\n  {}", posture_text(f[1], f[2], f[3]), f[4] == "1" ? "on" : "off",
                       ranges_text(f, 5, 24, "s"), clock_text(f[29]));
  if ((h == "P" || h == "F" || h == "D") && f.size() == 74)
    return fmt::format("pan-tilt {} by 5 deg sector, mm\n  {}\n  {}",
                       h == "P" ? "ranges" : h == "F" ? "filtered ranges" : "differences", ranges_text(f, 1, 72, "#"),
                       clock_text(f[73]));
  if (h == "E" && f.size() == 6)
    return fmt::format("emergency: {}{}cause {}  detectors {}{}{}  {}", f[2] == "1" ? "LATCHED  " : "",
                       f[1] == "1" ? "HELD (waiting for sensor data)  " : "", f[3],
                       (num(f[4]) & protocol::kDetectBumper) ? "bumper " : "",
                       (num(f[4]) & protocol::kDetectUltrasonic) ? "ultrasonic " : "",
                       (num(f[4]) & protocol::kDetectComm) ? "comm-loss" : "", clock_text(f[5]));
  if (h == "error" && f.size() > 1) return "error: " + reply.substr(6);
  if (h == "error") return sent.empty() ? "error" : "error (XB1 for the reason)";
  return reply;
}

bool emergency_banner(const std::string& xe_reply, std::string& what) {
  const auto f = split(xe_reply);
  if (f.size() != 6 || f[0] != "E") return false;
  if (f[2] == "1") {
    what = fmt::format("*** EMERGENCY LATCHED: {} — the robot is stopped; XR re-enables once the cause is gone ***", f[3]);
    return true;
  }
  if (f[1] == "1") {
    what = "*** motion held: waiting for watch-dog sensor data ***";
    return true;
  }
  return false;
}

}  // namespace robuter::ctl
