// SPDX-License-Identifier: GPL-3.0-or-later
// Sector k measured by the transducer looking 5k° from forward; readings corrected as read_pt().
#include "tests/ptu/scan_maker.hpp"

#include <cmath>
#include <numbers>

#include "hal/sim/rng.hpp"
#include "hal/sim/world_io.hpp"
#include "modules/ptu/scan_filter.hpp"

namespace robuter::test {

ScanMaker::ScanMaker(const std::string& world_file, std::uint64_t noise_seed) {
  auto w = sim::load_world(world_file);
  if (!w) return;
  world_ = std::make_unique<sim::World>(std::move(w).value());
  sim::SonarParams p = sim::default_pan_tilt_params();
  if (noise_seed != 0) {
    p.noise_sigma = 0.01;
    rng_ = std::make_unique<sim::Rng>(noise_seed);
  }
  model_ = std::make_unique<sim::SonarModel>(*world_, p);
}

ScanMaker::~ScanMaker() = default;

PanTiltScan ScanMaker::scan(double x, double y, double heading_deg, std::uint64_t tick) {
  PanTiltScan s;
  const sim::Pose pose{x, y, heading_deg * std::numbers::pi / 180.0};
  const SectorPose sp{static_cast<std::int32_t>(std::lround(x * 1e4)), static_cast<std::int32_t>(std::lround(y * 1e4)),
                      static_cast<std::int32_t>(std::lround(heading_deg * 100.0))};
  const sim::PanTiltMount mount;
  for (int k = 0; k < kPanTiltSectors; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const sim::PanTiltReading m = sim::measure_pan_tilt(*model_, pose, mount, k * 5.0 * std::numbers::pi / 180.0, rng_.get());
    s.raw[i] = ptu::correct_range(static_cast<std::int32_t>(std::lround(m.facing * 1000.0)));
    s.read_tick[i] = tick;
    s.direction[i] = 500 * k;
    s.pose[i] = sp;
  }
  ptu::spike_filter(s.raw, s.filtered);
  ptu::differences(s.filtered, s.differences);
  s.tick = tick;
  return s;
}

}  // namespace robuter::test
