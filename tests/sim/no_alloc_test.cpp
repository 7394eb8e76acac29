// SPDX-License-Identifier: GPL-3.0-or-later
// The periodic path allocates nothing: robot steps (with contacts) and sonar readings (ring with
// noise, pan-tilt) are run with a counting global operator new.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cstdlib>
#include <new>

#include "hal/sim/robot.hpp"
#include "hal/sim/sonar_layout.hpp"
#include "hal/sim/sonar_presets.hpp"
#include "hal/sim/world_io.hpp"
#include "tests/sim/sim_test_util.hpp"

namespace {
std::atomic<long> g_allocations{0};    // allocations seen while counting
std::atomic<bool> g_counting{false};   // whether allocations are being counted
}  // namespace

// Counting replacements of the global allocation functions (the whole test program uses them).
// They pair operator new with malloc and operator delete with free, which GCC cannot see.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t n) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1);
  if (void* p = std::malloc(n != 0 ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace robuter::sim {
namespace {

TEST(RealTime, StepsAndReadingsDoNotAllocate) {
  auto loaded = load_world(test::world_path("default.toml"));
  ASSERT_TRUE(loaded.ok());
  const World& world = loaded.value();
  RobotParams rp;
  rp.odometry.noise = 0.01;
  rp.odometry.slip_sigma = 0.01;
  Robot robot(world, rp, *world.start);
  SonarParams sp = default_ring_params();
  sp.noise_sigma = 0.01;
  sp.spurious_probability = 0.05;
  sp.dropout_probability = 0.05;
  SonarModel ring(world, sp);
  SonarParams realistic = default_ring_params();
  apply_sonar_preset(SonarPreset::realistic, realistic);
  SonarModel ring_realistic(world, realistic);  // multipath and cross-talk: more traces, no allocation
  std::array<double, 4> node{};
  SonarModel ptu(world, default_pan_tilt_params());
  const RingLayout layout = default_ring_layout();
  const PanTiltMount mount;
  Rng rng(5);
  double sum = 0.0;
  g_allocations = 0;
  g_counting = true;
  robot.command({0.6, 0.6});  // straight into the east side of the west room: contacts
  for (int k = 0; k < 2000; ++k) {
    if (k == 1200) robot.command({-0.3, 0.3});
    robot.step(0.01);
    if (k % 4 == 0) {
      for (const auto& m : layout) sum += ring.measure(robot.pose(), m, &rng);
      for (std::size_t n = 0; n < layout.size(); n += node.size()) {
        ring_realistic.measure_firing(robot.pose(), std::span<const SonarMount>(layout).subspan(n, node.size()), node, &rng);
        for (const double r : node) sum += r;
      }
    }
    if (k % 3 == 0) {
      const PanTiltReading r = measure_pan_tilt(ptu, robot.pose(), mount, 0.05 * k, &rng);
      sum += r.facing + r.opposite;
    }
  }
  g_counting = false;
  EXPECT_EQ(g_allocations.load(), 0);
  EXPECT_TRUE(robot.bumper() || robot.travelled() > 1.0);
  EXPECT_GT(sum, 0.0);
}

}  // namespace
}  // namespace robuter::sim
