// SPDX-License-Identifier: GPL-3.0-or-later
// The passage estimate on scans the simulator's sonar model makes in the shipped door worlds:
// centre, direction and width against the true door from every start the door tests use.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "modules/gate/door_estimate.hpp"
#include "tests/ptu/scan_maker.hpp"

namespace robuter::gate {
namespace {

constexpr double kRad = std::numbers::pi / 180.0;

// The door of door90/door100: centred at x = 3 m in the wall y = 3.95 (near face) … 4.05 m.
struct Truth {
  double cx = 3.0, cy = 3.95;  // centre of the near face's opening, m (world)
};

// The estimate (robot frame) taken back to the world frame for a robot at (x, y, heading).
struct World {
  double cx, cy, normal_deg, width;
};
World to_world(const DoorEstimate& d, double x, double y, double heading_deg) {
  const double th = heading_deg * kRad;
  const double cx = d.center_x / 1000.0, cy = d.center_y / 1000.0;
  return {x + cx * std::cos(th) - cy * std::sin(th), y + cx * std::sin(th) + cy * std::cos(th),
          ptu::wrap_deg(d.normal_deg + heading_deg), d.width_mm};
}

DoorEstimate estimate(test::ScanMaker& m, double x, double y, double heading_deg) {
  const PanTiltScan s = m.scan(x, y, heading_deg);
  ptu::Echoes e;
  const SectorPose now = s.pose[0];
  ptu::locate_echoes(s, now, 1, 100, ptu::EchoGeometry{}, e);
  return estimate_door(s, e, DoorSettings{});
}

void check(const char* world, double width_m, double dist, double max_lateral, double max_heading, double tol_mm,
           double tol_deg) {
  test::ScanMaker m(std::string(ROBUTER_WORLDS_DIR "/") + world);
  ASSERT_TRUE(m.ok());
  for (double lateral : {-max_lateral, -0.5 * max_lateral, 0.0, 0.5 * max_lateral, max_lateral})
    for (double heading : {-max_heading, 0.0, max_heading}) {
      const double x = 3.0 + lateral, y = 3.95 - dist, h = 90.0 + heading;
      const DoorEstimate d = estimate(m, x, y, h);
      ASSERT_TRUE(d.ok) << world << " lateral " << lateral << " heading " << heading;
      const World w = to_world(d, x, y, h);
      EXPECT_NEAR(w.cx, 3.0, tol_mm / 1000.0) << lateral << " " << heading;
      EXPECT_NEAR(w.cy, 3.95, tol_mm / 1000.0) << lateral << " " << heading;
      EXPECT_NEAR(w.normal_deg, 90.0, tol_deg) << lateral << " " << heading;
      EXPECT_NEAR(w.width, width_m * 1000.0, 2.5 * tol_mm) << lateral << " " << heading;
    }
}

// From the door tests' starting line (axle 1.5 m from the wall, ±40 cm, ±20°): centre within
// 3 cm, direction within 0.5°.
TEST(DoorEstimate, Door90FromTheStartingLine) { check("door90.toml", 0.90, 1.5, 0.4, 20.0, 30.0, 0.5); }
TEST(DoorEstimate, Door100FromTheStartingLine) { check("door100.toml", 1.00, 1.5, 0.4, 20.0, 30.0, 0.5); }
// From about where the passage finder checks its alignment (front face 0.3 m from the wall,
// within 10 cm and 5° of the centre line): centre within 2 cm, direction within 1°.
TEST(DoorEstimate, Door90FromTheStagingLine) { check("door90.toml", 0.90, 0.995, 0.1, 5.0, 20.0, 1.0); }
TEST(DoorEstimate, Door100FromTheStagingLine) { check("door100.toml", 1.00, 0.995, 0.1, 5.0, 20.0, 1.0); }

// The 70 cm gap from the starting line: too narrow for the beam to see through (2 × 12.5° of
// beam against 26° of gap), so no passage locks — the seed's method cannot find it.
TEST(DoorEstimate, Gap70DoesNotLockFromTheStartingLine) {
  test::ScanMaker m(ROBUTER_WORLDS_DIR "/gap70.toml");
  ASSERT_TRUE(m.ok());
  EXPECT_FALSE(estimate(m, 3.0, 2.45, 90.0).ok);
}

}  // namespace
}  // namespace robuter::gate
