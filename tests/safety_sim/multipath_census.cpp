// SPDX-License-Identifier: GPL-3.0-or-later
// The multipath census (multipath_census.hpp): a wanderer's ring into an evidence grid, clearings judged by the world.
#include "tests/safety_sim/multipath_census.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "hal/sim/footprint.hpp"
#include "hal/sim/robot.hpp"
#include "hal/sim/sonar_layout.hpp"
#include "hal/sim/world_io.hpp"
#include "tests/support/wanderer.hpp"

namespace robuter::test {

namespace {

constexpr double kOnSurface = 0.0125;  // a cell whose centre is this near a surface (half a cell) is on it, m
constexpr double kLonger = 0.05;       // a reading this much longer than the ideal model's is multipath, m

// Whether p lies within kCorner of a vertex of the world's solids (a surface's end).
bool near_vertex(const sim::World& world, const Eigen::Vector2d& p) {
  constexpr double kCorner = 0.05;  // m
  for (const auto& s : world.segments())
    if ((s.a - p).norm() <= kCorner || (s.b - p).norm() <= kCorner) return true;
  return false;
}

// A cell of evidence a cone may clear.
struct Seen {
  Eigen::Vector2d at;      // its centre, m
  std::uint64_t tick = 0;  // its evidence's tick
};

// The evidence cells within `reach` of `origin` (a superset of those one cone may clear: which it
// did is what the grid says after it, not a second copy of its geometry).
void evidence_near(const emergency::EvidenceGrid& g, std::uint64_t tick, const Eigen::Vector2d& origin, double reach,
                   std::vector<Seen>& out) {
  out.clear();
  const double cell = g.settings().cell;
  const int x0 = static_cast<int>(std::floor((origin.x() - reach) / cell)), x1 = static_cast<int>(std::floor((origin.x() + reach) / cell));
  const int y0 = static_cast<int>(std::floor((origin.y() - reach) / cell)), y1 = static_cast<int>(std::floor((origin.y() + reach) / cell));
  for (int gy = y0; gy <= y1; ++gy)
    for (int gx = x0; gx <= x1; ++gx) {
      const Eigen::Vector2d p((gx + 0.5) * cell, (gy + 0.5) * cell);
      if (g.state(p, tick, 1) == emergency::CellState::obstacle) out.push_back({p, g.evidence_tick(p)});
    }
}

// Evidence cells off every surface within kNear of `robot`.
long phantom_near(const emergency::EvidenceGrid& g, const sim::World& world, std::uint64_t tick, const Eigen::Vector2d& robot) {
  constexpr double kNear = 1.5;  // m
  const double cell = g.settings().cell;
  long n = 0;
  for (int gy = static_cast<int>(std::floor((robot.y() - kNear) / cell)); gy <= std::floor((robot.y() + kNear) / cell); ++gy)
    for (int gx = static_cast<int>(std::floor((robot.x() - kNear) / cell)); gx <= std::floor((robot.x() + kNear) / cell); ++gx) {
      const Eigen::Vector2d p((gx + 0.5) * cell, (gy + 0.5) * cell);
      if ((p - robot).norm() > kNear || g.state(p, tick, 1) != emergency::CellState::obstacle) continue;
      if (world.clearance(p) > kOnSurface) ++n;
    }
  return n;
}

}  // namespace

MultipathCensus multipath_census(const std::string& world_file, sim::SonarPreset preset, double seconds,
                                 std::uint64_t seed, const emergency::GridSettings& settings, std::uint64_t fresh) {
  MultipathCensus out;
  auto loaded = sim::load_world(world_file);
  if (!loaded.ok()) return out;
  const sim::World& world = loaded.value();
  sim::Robot robot(world, sim::RobotParams{}, world.start.value_or(sim::Pose{}));
  sim::SonarParams p = sim::default_ring_params();
  sim::apply_sonar_preset(preset, p);
  sim::SonarParams ideal_p = sim::default_ring_params();
  sim::apply_sonar_preset(sim::SonarPreset::ideal, ideal_p);
  sim::SonarModel ring(world, p), ideal(world, ideal_p);
  const sim::RingLayout layout = sim::default_ring_layout();
  sim::Rng rng(seed);
  emergency::EvidenceGrid grid(settings);
  const sim::Box body = sim::RobotGeometry{}.body();  // the robot model's body, robot frame
  std::array<double, sim::kRingSensors> ranges{};
  std::vector<Seen> before;
  Wanderer wanderer;
  const long ticks = std::lround(seconds * 100.0);
  for (long k = 1; k <= ticks; ++k) {
    const auto tick = static_cast<std::uint64_t>(k);
    const sim::Pose& at = robot.pose();
    grid.follow({at.x, at.y});
    if (k % 4 == 0) {
      for (std::size_t n = 0; n < layout.size(); n += 4)
        ring.measure_firing(at, std::span<const sim::SonarMount>(layout).subspan(n, 4),
                            std::span<double>(ranges).subspan(n, 4), &rng);
      for (std::size_t i = 0; i < layout.size(); ++i) {
        const auto& m = layout[i];
        const Eigen::Vector2d origin = sim::to_world(at, m.position);
        const double direction = at.theta + m.direction;
        const bool echo = ranges[i] > 0.0;
        const double range = echo ? ranges[i] : p.max_range();
        ++out.readings;
        // An echo longer than the ideal model's at the same pose came by another path (multipath).
        const double truth = echo ? ideal.measure(at, m) : 0.0;
        const bool longer = echo && (truth <= 0.0 || ranges[i] > truth + kLonger);
        before.clear();
        if (longer) {
          ++out.longer_than_truth;
          evidence_near(grid, tick, origin, std::min(range, settings.reach), before);
        }
        grid.certify_cone(tick, origin, direction, range, !echo, echo);
        for (const auto& c : before) {
          if (grid.state(c.at, tick, 1) == emergency::CellState::obstacle) continue;
          if (world.clearance(c.at) <= kOnSurface) {
            ++out.surface_cleared;
            if (tick <= c.tick + fresh) ++out.fresh_cleared;
            if (near_vertex(world, c.at)) ++out.corner_cleared;
          } else {
            ++out.phantom_cleared;
          }
        }
      }
      for (std::size_t i = 0; i < layout.size(); ++i)
        if (ranges[i] > 0.0)
          grid.mark_arc(tick, sim::to_world(at, layout[i].position), at.theta + layout[i].direction, ranges[i], false);
      robot.command(wanderer.decide(k, ranges, robot.bumper(), rng));
    }
    grid.certify_rectangle(tick, {at.x, at.y}, at.theta, body.lo, body.hi);
    if (k % 100 == 0) out.phantom_near += phantom_near(grid, world, tick, {at.x, at.y});
    robot.step(0.01);
  }
  out.travelled = robot.travelled();
  return out;
}

}  // namespace robuter::test
