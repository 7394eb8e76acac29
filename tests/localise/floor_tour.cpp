// SPDX-License-Identifier: GPL-3.0-or-later
// The building floor's corridor loop through the whole firmware (floor_tour.hpp).
#include "tests/localise/floor_tour.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hal/sim/geometry.hpp"
#include "hal/sim/world.hpp"
#include "modules/firmware/sim_firmware.hpp"
#include "modules/localise/map_frame.hpp"

namespace robuter::test {
namespace {

// The corridor loop of the library's floor bench (lab_tour.cpp floor_loop): the 53 m east-west
// corridor end to end, the two north-south corridors up and down, ≈ 225 m a lap.
const std::vector<Eigen::Vector2d> kLoop = {{6.0, 20.05},  {21.15, 20.05}, {21.15, 34.6}, {21.15, 5.45}, {21.15, 20.05},
                                            {43.1, 20.05}, {43.1, 34.6},   {43.1, 5.45},  {43.1, 20.05}, {59.0, 20.05}};

double wrap(double a) { return std::remainder(a, 2.0 * M_PI); }

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * static_cast<double>(v.size())))];
}

struct Errors {
  double position = 0.0;  // m
  double heading = 0.0;   // rad
};

// The map pose (the firmware's) and the odometry against the truth.
Errors map_error(SimFirmware& fw) {
  const executor::PostureUnits m = localise::map_posture(fw.bb().posture.reader().peek(), fw.bb().localisation.reader().peek());
  const auto& t = fw.sim().robot().pose();
  return {std::hypot(m.x * 1e-4 - t.x, m.y * 1e-4 - t.y), std::abs(wrap(m.theta * 1e-2 * M_PI / 180.0 - t.theta))};
}
Errors odometry_error(SimFirmware& fw) {
  const auto& o = fw.sim().robot().odometry();
  const auto& t = fw.sim().robot().pose();
  return {std::hypot(o.x - t.x, o.y - t.y), std::abs(wrap(o.theta - t.theta))};
}

constexpr double kKidnapClearance = 0.6;  // m: a kidnapping puts the robot this clear of every wall

// An operator's client: every 0.2 s an AM towards the next point of the loop, by the true pose.
class Driver {
 public:
  explicit Driver(SimFirmware& fw) : fw_(fw) {}
  void tick(int i) {
    if (i % 20 != 0) return;
    const auto& p = fw_.sim().robot().pose();
    Eigen::Vector2d to = kLoop[next_] - Eigen::Vector2d(p.x, p.y);
    if (to.norm() < 0.3) {
      next_ = (next_ + 1) % kLoop.size();
      to = kLoop[next_] - Eigen::Vector2d(p.x, p.y);
    }
    const double e = wrap(std::atan2(to.y(), to.x()) - p.theta);
    long left = 0, right = 0;
    if (std::abs(e) > 0.35) {  // turn in place towards it
      left = e > 0 ? -15 : 15;
      right = -left;
    } else {
      left = std::lround(30.0 - 40.0 * e);
      right = std::lround(30.0 + 40.0 * e);
    }
    (void)fw_.ask("AM " + std::to_string(left) + " " + std::to_string(right), 5);
  }
  // Where the loop goes from the robot: the unit direction to the next point.
  Eigen::Vector2d heading_to_next() const {
    const auto& p = fw_.sim().robot().pose();
    return (kLoop[next_] - Eigen::Vector2d(p.x, p.y)).normalized();
  }

 private:
  SimFirmware& fw_;
  std::size_t next_ = 1;
};

}  // namespace

FloorTourResult run_floor_tour(const FloorTourSpec& spec) {
  FloorTourResult out;
  hal::SimOptions sim;
  sim.world_file = ROBUTER_WORLDS_DIR "/building_floor.toml";
  sim.seed = spec.seed;
  sim.odometry_noise = true;
  sim.sonar_model = spec.sonar_model;
  Config cfg;
  cfg.places.file = ROBUTER_WORLDS_DIR "/building_floor.places.toml";
  cfg.localise.enabled = true;
  SimFirmware fw(sim.world_file, cfg, sim);
  if (!fw.ok()) {
    std::printf("firmware: %s\n", fw.error().c_str());
    return out;
  }
  out.ok = true;
  fw.run_ticks(20);
  // The floor's start, (3.0, 20.05) facing east: AC says where the robot is, as an operator does.
  const auto& start = fw.sim().robot().pose();
  (void)fw.ask("AC " + std::to_string(std::lround(start.x * 1e4)) + " " + std::to_string(std::lround(start.y * 1e4)) + " " +
               std::to_string(std::lround(start.theta * 18000.0 / M_PI)));
  (void)fw.ask("ASN");
  Driver driver(fw);
  std::vector<double> pos, head, odo_pos, odo_head;
  const int kidnap_tick = static_cast<int>(std::lround(spec.kidnap_at * 100.0));
  int kidnapped = -1;  // the tick the robot was carried at
  int found_after = -1, good = 0;
  const int ticks = static_cast<int>(spec.seconds * 100.0) + (spec.kidnap ? kidnap_tick + 6000 : 0);
  for (int i = 0; i < ticks; ++i) {
    driver.tick(i);
    fw.step();
    if (spec.kidnap && kidnapped < 0 && i >= kidnap_tick && i % 100 == 0) {
      // Carried 3 m along the loop (back or on) to a spot clear of every wall; the odometry is not told.
      auto& robot = fw.sim().robot();
      auto p = robot.pose();
      const Eigen::Vector2d d = driver.heading_to_next();
      for (const double sign : {spec.kidnap_back ? -1.0 : 1.0, spec.kidnap_back ? 1.0 : -1.0}) {
        const Eigen::Vector2d to(p.x + sign * 3.0 * d.x(), p.y + sign * 3.0 * d.y());
        if (robot.world().clearance(to) < kKidnapClearance) continue;
        out.kidnapped_at = i / 100.0;
        out.kidnap_x = p.x;
        out.kidnap_y = p.y;
        const auto odo = robot.odometry();
        const auto wheels = robot.commanded();  // place() forgets the drive's command; the drive does not resend it
        p.x = to.x();
        p.y = to.y();
        robot.place(p);
        robot.set_odometry(odo);
        robot.command(wheels);
        kidnapped = i;
        break;
      }
    }
    if (i % 20 != 0) continue;
    const Errors m = map_error(fw);
    if (spec.trace && i % 100 == 0) {
      const Localisation& l = fw.bb().localisation.reader().peek();
      const auto& t = fw.sim().robot().pose();
      std::printf("t %.0f truth %.2f %.2f %.0f  map error %.0f mm  state %d estimate %.2f %.2f %.0f major %d cluster %u%% particles %u\n",
                  i / 100.0, t.x, t.y, t.theta * 180.0 / M_PI, m.position * 1000.0, static_cast<int>(l.state), l.x * 1e-4, l.y * 1e-4, l.theta * 0.01,
                  l.major_mm, static_cast<unsigned>(l.cluster_pct), static_cast<unsigned>(l.particles));
    }
    if (spec.kidnap) {
      if (kidnapped < 0 || i <= kidnapped || found_after >= 0) continue;
      if (i > kidnapped + static_cast<int>(spec.seconds * 100.0)) break;
      good = m.position <= 0.2 && m.heading <= 10.0 * M_PI / 180.0 ? good + 1 : 0;
      if (good >= 10) found_after = i - kidnapped - 9 * 20;
      continue;
    }
    if (i % 100 != 0) continue;
    const Errors o = odometry_error(fw);
    pos.push_back(m.position);
    head.push_back(m.heading);
    odo_pos.push_back(o.position);
    odo_head.push_back(o.heading);
  }
  const Localisation& l = fw.bb().localisation.reader().peek();
  const EmergencyState& e = fw.bb().emergency.reader().peek();
  out.driven = fw.sim().robot().travelled();
  out.map_p95 = percentile(pos, 0.95);
  out.map_heading_p95 = percentile(head, 0.95);
  out.map_worst = percentile(pos, 1.0);
  out.map_heading_worst = percentile(head, 1.0);
  out.odometry_p95 = percentile(odo_pos, 0.95);
  out.odometry_heading_p95 = percentile(odo_head, 0.95);
  out.found_after = found_after < 0 ? -1.0 : found_after / 100.0;
  out.protective_stops = e.protective_stops;
  out.trips = e.trips;
  out.run_us_max = l.run_us_max;
  out.scouts_fired = l.scouts_fired;
  return out;
}

}  // namespace robuter::test
