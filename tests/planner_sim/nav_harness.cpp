// SPDX-License-Identifier: GPL-3.0-or-later
// The navigation harness: stepping, invariants, figures and optional pictures.
#include "tests/planner_sim/nav_harness.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "hal/sim/footprint.hpp"
#include "modules/planner/picture_writer.hpp"

namespace robuter::test {

namespace {
// Distance between two segments (they do not cross when the bumper is not pressed).
double segment_distance(const sim::Vec2& a, const sim::Vec2& b, const sim::Vec2& c, const sim::Vec2& d) {
  auto point_seg = [](const sim::Vec2& p, const sim::Vec2& s0, const sim::Vec2& s1) {
    const sim::Vec2 u = s1 - s0;
    const double l2 = u.squaredNorm();
    const double t = l2 > 0 ? std::clamp((p - s0).dot(u) / l2, 0.0, 1.0) : 0.0;
    return (s0 + t * u - p).norm();
  };
  return std::min({point_seg(a, c, d), point_seg(b, c, d), point_seg(c, a, b), point_seg(d, a, b)});
}

bool navigating(PlannerState s) {
  return s == PlannerState::scanning || s == PlannerState::planning || s == PlannerState::moving;
}
}  // namespace

PlannerModule* planner_of(SimFirmware& fw) {
  const auto i = fw.kernel().find("planner");
  return i ? dynamic_cast<PlannerModule*>(fw.kernel().row(*i).process) : nullptr;
}

double body_clearance(SimFirmware& fw) {
  sim::Vec2 corners[4];
  sim::footprint_corners(sim::RobotGeometry{}, fw.sim().robot().pose(), corners);
  double best = 1e9;
  for (const sim::Segment& s : fw.sim().world().segments())
    for (int i = 0; i < 4; ++i) best = std::min(best, segment_distance(corners[i], corners[(i + 1) % 4], s.a, s.b));
  return best;
}

NavRecord run_navigation(SimFirmware& fw, int max_ticks, double goal_x, double goal_y, const std::string& /*label*/) {
  NavRecord rec;
  PlannerModule* pm = planner_of(fw);
  if (pm == nullptr) return rec;
  const double t0 = fw.seconds(), d0 = fw.sim().robot().travelled();
  const std::uint32_t trips0 = fw.bb().emergency.reader().peek().trips;
  std::uint32_t plans_seen = 0;
  // The goal was asked just before: let the planner take it (it runs every 10 ticks).
  const std::uint32_t seq = fw.bb().planner_status.reader().peek().goal_seq;
  fw.run_until([&] { return fw.bb().planner_status.reader().peek().goal_seq != seq; }, 20);
  for (int i = 0; i < max_ticks && navigating(pm->state()); ++i) {
    fw.step();
    rec.bumper = rec.bumper || fw.sim().robot().bumper();
    if (i % 10 == 0) rec.min_clearance = std::min(rec.min_clearance, body_clearance(fw));
    const PlannerStatus& st = fw.bb().planner_status.reader().peek();
    if (st.plans != plans_seen) rec.plan_times += std::to_string(st.plan_us) + " ";
    plans_seen = st.plans;
  }
  const PlannerStatus& st = fw.bb().planner_status.reader().peek();
  rec.state = pm->state();
  fw.step();  // the last plan's picture, if any, is drawn after the tick that made it
  if (auto* w = fw.firmware().planner_pictures()) rec.pictures = static_cast<int>(w->written());
  rec.plans = st.plans;
  rec.scans = st.scans;
  rec.run_us_max = st.run_us_max;
  rec.whole_fields = pm->planner().whole_fields();
  rec.seconds = fw.seconds() - t0;
  rec.travelled = fw.sim().robot().travelled() - d0;
  rec.trips = fw.bb().emergency.reader().peek().trips - trips0;
  const sim::Pose& p = fw.sim().robot().pose();
  rec.final_error = std::hypot(p.x - goal_x, p.y - goal_y);
  return rec;
}

}  // namespace robuter::test
