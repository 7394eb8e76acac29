// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers of the safety acceptance tests: temporary worlds, reply parsing, true clearance, monitor.
#include "tests/safety_sim/support.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "hal/sim/geometry.hpp"
#include "hal/sim/world_io.hpp"

namespace robuter::test::safety_sim {

// A private folder per world, so tests running in parallel never share a file.
TempWorld::TempWorld(const std::string& toml) {
  char tmpl[] = "/tmp/robuter-safety-world-XXXXXX";
  const char* d = mkdtemp(tmpl);
  dir_ = d ? d : "/tmp";
  path_ = dir_ + "/world.toml";
  std::ofstream(path_) << toml;
}

// The folder goes with the world (the firmware read the file at start-up).
TempWorld::~TempWorld() {
  std::error_code ec;
  if (dir_ != "/tmp") std::filesystem::remove_all(dir_, ec);
}

// Only the rows the safety core needs; the firmware skips the others (modules.enabled).
Config core_config() {
  Config c;
  c.enabled_modules = std::vector<std::string>{"sim", "heartbeat", "serial", "us", "emergency", "executor"};
  return c;
}

Config seed_rule_config(Config c) {
  c.emergency.rule = "seed";
  return c;
}

Config envelope_rule_config(Config c) {
  c.emergency.rule = "envelope";
  return c;
}

// The same conversion as SimRobot, so clearances are measured on the body the simulator moves.
sim::RobotGeometry geometry(const Config& cfg) {
  sim::RobotGeometry g;
  g.length = cfg.robot.length_mm / 1000.0;
  g.width = cfg.robot.width_mm / 1000.0;
  g.wheel_base = cfg.robot.wheel_base_mm / 1000.0;
  return g;
}

// The loader the firmware uses, so a world accepted here is accepted there.
std::optional<std::string> check_world(const std::string& toml, const Config& cfg) {
  auto w = sim::parse_world_toml(toml, "generated.toml", geometry(cfg));
  if (!w) return w.error().describe();
  return std::nullopt;
}

namespace {
// The point of an axis-aligned box nearest to p (p itself inside): one term of segment-to-box.
sim::Vec2 nearest_in_box(const sim::Vec2& p, const sim::Box& b) {
  return {std::clamp(p.x(), b.lo.x(), b.hi.x()), std::clamp(p.y(), b.lo.y(), b.hi.y())};
}

// Distance between a segment and a box, and the box point that realises it: 0 where they meet,
// else the nearest pair involves an end of the segment or a corner of the box.
double segment_box_distance(const sim::Vec2& a, const sim::Vec2& b, const sim::Box& box, sim::Vec2& on_box) {
  if (sim::segment_meets_box(a, b, box)) {
    on_box = nearest_in_box(0.5 * (a + b), box);
    return 0.0;
  }
  double d = 1e18;
  for (const sim::Vec2& e : {a, b}) {
    const sim::Vec2 q = nearest_in_box(e, box);
    if ((e - q).norm() < d) {
      d = (e - q).norm();
      on_box = q;
    }
  }
  const sim::Vec2 corners[4] = {box.lo, {box.hi.x(), box.lo.y()}, box.hi, {box.lo.x(), box.hi.y()}};
  for (const auto& c : corners) {
    const double dc = sim::point_segment_distance(c, a, b);
    if (dc < d) {
      d = dc;
      on_box = c;
    }
  }
  return d;
}
}  // namespace

// Every edge, in the robot frame where the body is an axis-aligned box.
double body_clearance(const sim::World& world, const sim::RobotGeometry& g, const sim::Pose& pose, sim::Vec2* where) {
  const sim::Box body = g.body();
  double best = 1e9;
  sim::Vec2 at = sim::Vec2::Zero();
  for (const sim::Segment& s : world.segments()) {
    sim::Vec2 q = sim::Vec2::Zero();
    const double d = segment_box_distance(sim::to_local(pose, s.a), sim::to_local(pose, s.b), body, q);
    if (d < best) {
      best = d;
      at = q;
    }
  }
  if (where) *where = at;
  return best;
}

// The body's world bounding box, grown by `reach`, selects the edges worth measuring.
double body_clearance_near(const sim::World& world, const sim::RobotGeometry& g, const sim::Pose& pose, double reach,
                           sim::GridScratch& scratch, sim::Vec2* where) {
  sim::Vec2 corners[4];
  sim::footprint_corners(g, pose, corners);
  sim::Vec2 lo = corners[0], hi = corners[0];
  for (const auto& c : corners) {
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  const sim::Vec2 pad = sim::Vec2::Constant(reach);
  const sim::Box body = g.body();
  double best = reach;
  sim::Vec2 at = sim::Vec2::Zero();
  const auto& segs = world.segments();
  world.grid().for_each_near(lo - pad, hi + pad, scratch, [&](std::uint32_t i) {
    sim::Vec2 q = sim::Vec2::Zero();
    const double d = segment_box_distance(sim::to_local(pose, segs[i].a), sim::to_local(pose, segs[i].b), body, q);
    if (d < best) {
      best = d;
      at = q;
    }
  });
  if (where) *where = at;
  return best;
}

// Replies are checked field by field, so a malformed one is a failure, not a zero.
std::optional<BoReply> parse_bo(const std::optional<std::string>& reply) {
  if (!reply) return std::nullopt;
  BoReply r;
  if (std::sscanf(reply->c_str(), "S %d %d %d %d %lld", &r.x, &r.y, &r.theta, &r.servo, &r.clock) != 5)
    return std::nullopt;
  return r;
}

// The cause is a word: read with a stream rather than scanf.
std::optional<XeReply> parse_xe(const std::optional<std::string>& reply) {
  if (!reply) return std::nullopt;
  std::istringstream in(*reply);
  std::string tag;
  XeReply r;
  if (!(in >> tag >> r.held >> r.latched >> r.cause >> r.enabled >> r.clock >> r.granted_pct >> r.rule >> r.protective) ||
      tag != "E")
    return std::nullopt;
  return r;
}

// What really reached the motors, not what the gate or the executor meant to send.
Wheels commanded(SimFirmware& fw) {
  Wheels w;
  fw.sim().drive().commanded(w.left, w.right);
  return w;
}

std::string sensor_list(std::uint32_t mask) {
  std::string out;
  for (int s = 1; s <= 24; ++s)
    if (mask & (1u << (s - 1))) out += (out.empty() ? "" : ",") + std::to_string(s);
  return "{" + out + "}";
}

// The harness calls the observer after every tick, including those inside ask().
void SafetyMonitor::attach(SimFirmware& fw) {
  fw_ = &fw;
  geom_ = fw.sim().robot().params().geometry;
  scratch_.prepare(fw.sim().world().segments().size());
  fw.set_tick_observer([this] { check(); });
}

// Counting all but describing the first keeps the report short and reproducible.
void SafetyMonitor::violation(std::uint64_t& counter, const std::string& what) {
  ++counter;
  if (first_violation.empty()) first_violation = what;
}

// Clearances beyond this are not told apart (the monitor reports the closest approach), m.
constexpr double kClearanceReach = 0.5;

// The tick just run is kernel().tick() − 1; everything is read after it ended.
void SafetyMonitor::check() {
  SimFirmware& fw = *fw_;
  ++ticks;
  const std::uint64_t tick = fw.kernel().tick() - 1;
  const EmergencyState& e = fw.bb().emergency.reader().peek();
  const MotionCommand& c = fw.bb().motion_command.reader().peek();
  const Wheels w = commanded(fw);
  if (e.latched) ++latched_ticks;
  if (!w.zero()) {
    ++moving_ticks;
    last_moving_ = w;
  }
  const bool disagrees = !w.zero() && (e.latched || c.stop || c.left != w.left || c.right != w.right);
  disagreement_ = disagrees ? disagreement_ + 1 : 0;
  longest_disagreement = std::max(longest_disagreement, disagreement_);
  if (e.latched && !w.zero())
    violation(latched_moving, "tick " + std::to_string(tick) + ": drive at " + std::to_string(w.left) + " " +
                                  std::to_string(w.right) + " cm/s while latched");
  if (!w.zero() && (c.stop || c.left != w.left || c.right != w.right))
    violation(ungranted, "tick " + std::to_string(tick) + ": drive at " + std::to_string(w.left) + " " +
                             std::to_string(w.right) + " cm/s, gate grants " + std::to_string(c.left) + " " +
                             std::to_string(c.right) + (c.stop ? " (stop)" : ""));
  const bool us_on = (e.enabled & kDetectUltrasonic) != 0;
  const auto& robot = fw.sim().robot();
  if (robot.bumper() && !touching_) touch_began_us_on_ = us_on;
  touching_ = robot.bumper();
  // A contact is the ring's when it began with the detection on, or when the drive still moves
  // once the detection is back on.
  const bool rings = touch_began_us_on_ || !w.zero();
  if (us_on) {
    ++us_on_ticks;
    sim::Vec2 at;
    const double clear = body_clearance_near(fw.sim().world(), geom_, robot.pose(), kClearanceReach, scratch_, &at);
    min_clearance_us_on = std::min(min_clearance_us_on, clear);
    if (robot.bumper() && !rings) {
      ++contact_us_off;  // began with the detection lowered, still touching after it came back
    } else if (robot.bumper() && contact_us_on == 0) {
      contact_motion = last_moving_;
      contact_while_stopping = w.zero();
      contact_point = at;
    }
    if (robot.bumper() && rings)
      violation(contact_us_on, "tick " + std::to_string(tick) + ": contact with the ultrasonic detection on at (" +
                                   std::to_string(robot.pose().x) + ", " + std::to_string(robot.pose().y) + ", " +
                                   std::to_string(robot.pose().theta) + ")");
  } else if (robot.bumper()) {
    ++contact_us_off;
  }
}

}  // namespace robuter::test::safety_sim
