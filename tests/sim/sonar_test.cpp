// SPDX-License-Identifier: GPL-3.0-or-later
// Sonar ranges against hand-computed geometry: normal incidence, oblique and grazing surfaces,
// the beam cone, time-out range, blanking, occlusion, noise, and the pan-tilt's pair.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "hal/sim/sonar_layout.hpp"
#include "hal/sim/world_io.hpp"
#include "tests/sim/sim_test_util.hpp"
#include "tests/support/sample.hpp"

namespace robuter::sim {
namespace {

// A straight wall through point p with unit normal at angle `normal` (rad), 20 m long.
std::vector<Vec2> wall(const Vec2& p, double normal) {
  const Vec2 t(-std::sin(normal), std::cos(normal));
  return {p - 10.0 * t, p + 10.0 * t};
}

// A world holding only that wall.
World one_wall(const Vec2& p, double normal) {
  World w;
  w.add_obstacle({"wall", wall(p, normal), 0});
  w.finalize();
  return w;
}

TEST(Sonar, NormalIncidenceGivesThePerpendicularDistance) {
  const World world = one_wall({2.0, 0.0}, 0.0);
  SonarModel model(world, SonarParams{});
  const Echo e = model.trace({0.0, 0.0}, 0.0);
  ASSERT_TRUE(e.found);
  EXPECT_DOUBLE_EQ(e.range, 2.0);
  EXPECT_NEAR(e.incidence, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(model.measure_from({0.0, 0.0}, 0.0), 2.0);
}

// A wall whose normal is 30° off the beam: the perpendicular foot is outside the 12.5° cone,
// so the echo comes from the cone edge nearest it, at p / cos(30° - 12.5°), incidence 17.5°.
TEST(Sonar, ObliqueWallEchoesFromTheConeEdge) {
  const double n = deg_to_rad(30.0);
  const World world = one_wall({2.0 * std::cos(n) * std::cos(n), 2.0 * std::cos(n) * std::sin(n)}, n);
  SonarModel model(world, SonarParams{});
  const Echo e = model.trace({0.0, 0.0}, 0.0);
  ASSERT_TRUE(e.found);
  const double p = 2.0 * std::cos(n);  // distance of the wall's line from the sensor
  EXPECT_NEAR(e.range, p / std::cos(deg_to_rad(17.5)), 1e-12);
  EXPECT_NEAR(rad_to_deg(e.incidence), 17.5, 1e-9);
  EXPECT_NEAR(std::atan2(e.point.y(), e.point.x()), deg_to_rad(12.5), 1e-12);
}

// Normal 60° off the beam: the least oblique in-cone ray meets it at 47.5° > 40°: no echo.
// Allowing 50° brings the echo back at p / cos(47.5°).
TEST(Sonar, GrazingIncidenceIsMissed) {
  const double n = deg_to_rad(60.0);
  const double p = 1.0;
  const World world = one_wall({p * std::cos(n), p * std::sin(n)}, n);
  SonarParams params;
  SonarModel model(world, params);
  EXPECT_FALSE(model.trace({0.0, 0.0}, 0.0).found);
  EXPECT_EQ(model.measure_from({0.0, 0.0}, 0.0), 0.0);
  params.max_incidence = deg_to_rad(50.0);
  model.set_params(params);
  const Echo e = model.trace({0.0, 0.0}, 0.0);
  ASSERT_TRUE(e.found);
  EXPECT_NEAR(e.range, p / std::cos(deg_to_rad(47.5)), 1e-12);
  EXPECT_NEAR(rad_to_deg(e.incidence), 47.5, 1e-9);
}

// A 10 cm post whose near face is 2 m away, centred `off` degrees off the beam axis. The face
// spans ±1.43°: its foot is in the 12.5° cone up to 12.5° off (range 2 m), at 13° only the face's
// edge part is in the cone (range 2 / cos 0.5°), at 15° nothing is.
TEST(Sonar, ConeHalfAngleDecidesWhatIsSeen) {
  for (const double off : {0.0, 10.0, 12.0, 13.0, 15.0}) {
    SCOPED_TRACE(off);
    const double a = deg_to_rad(off);
    const Vec2 u(std::cos(a), std::sin(a)), v(-std::sin(a), std::cos(a));
    const Vec2 c = 2.05 * u;
    World w;
    w.add_obstacle({"post", {c - 0.05 * u - 0.05 * v, c + 0.05 * u - 0.05 * v,
                             c + 0.05 * u + 0.05 * v, c - 0.05 * u + 0.05 * v}, 0});
    w.finalize();
    SonarModel model(w, SonarParams{});
    const Echo e = model.trace({0.0, 0.0}, 0.0);
    if (off <= 12.5) {
      ASSERT_TRUE(e.found);
      EXPECT_NEAR(e.range, 2.0, 1e-12);
    } else if (off == 13.0) {
      ASSERT_TRUE(e.found);
      EXPECT_NEAR(e.range, 2.0 / std::cos(deg_to_rad(0.5)), 1e-12);
      EXPECT_NEAR(rad_to_deg(e.incidence), 0.5, 1e-9);
    } else {
      EXPECT_FALSE(e.found);
    }
  }
}

TEST(Sonar, WiderConeSeesFurtherOffAxis) {
  World w;
  w.add_obstacle({"post", test::rect(1.95, 0.50, 2.05, 0.60), 0});  // 13.7° to 17.1° off axis
  w.finalize();
  SonarParams p;
  SonarModel model(w, p);
  EXPECT_FALSE(model.trace({0.0, 0.0}, 0.0).found);
  p.half_angle = deg_to_rad(15.0);
  model.set_params(p);
  const Echo e = model.trace({0.0, 0.0}, 0.0);
  ASSERT_TRUE(e.found);
  // The near face x = 1.95 echoes from its corner nearest the axis (incidence 14.4°).
  EXPECT_NEAR(e.range, std::hypot(1.95, 0.50), 1e-12);
  EXPECT_NEAR(e.incidence, std::atan2(0.50, 1.95), 1e-12);
}

// Range = time-out × speed / 2 = 0.033 × 300 / 2 = 4.95 m.
TEST(Sonar, MaximumRangeFromTheTimeOut) {
  SonarParams p;
  EXPECT_DOUBLE_EQ(p.max_range(), 4.95);
  const World near = one_wall({4.94, 0.0}, 0.0);
  const World far = one_wall({4.96, 0.0}, 0.0);
  SonarModel a(near, p), b(far, p);
  EXPECT_NEAR(a.measure_from({0.0, 0.0}, 0.0), 4.94, 1e-12);
  EXPECT_EQ(b.measure_from({0.0, 0.0}, 0.0), 0.0);
}

TEST(Sonar, TooNearSurfacesBlindTheSensor) {
  const World world = one_wall({0.1, 0.0}, 0.0);
  SonarModel model(world, SonarParams{});
  EXPECT_FALSE(model.trace({0.0, 0.0}, 0.0).found);
  EXPECT_EQ(model.measure_from({0.0, 0.0}, 0.0), 0.0);
}

// A surface behind the sensor is not seen.
TEST(Sonar, NothingBehindTheSensor) {
  const World world = one_wall({-1.0, 0.0}, 0.0);
  SonarModel model(world, SonarParams{});
  EXPECT_FALSE(model.trace({0.0, 0.0}, 0.0).found);
  EXPECT_TRUE(model.trace({0.0, 0.0}, kPi).found);
}

// A wall at 30° to the beam is met at 47.5° or more inside the cone (no echo); crossing the
// whole cone, it hides the wall behind it. Cut short so that it only covers the upper part of
// the cone, the far wall's normal point is visible again.
TEST(Sonar, GrazingSurfacesStillHide) {
  const Vec2 t(std::cos(deg_to_rad(30.0)), std::sin(deg_to_rad(30.0)));
  const Vec2 c(1.5, 0.0);
  World w;
  w.add_obstacle({"far", wall({4.0, 0.0}, 0.0), 0});
  w.add_obstacle({"slant", {c - 2.0 * t, c + 2.0 * t}, 0});
  w.finalize();
  SonarModel model(w, SonarParams{});
  EXPECT_FALSE(model.trace({0.0, 0.0}, 0.0).found);
  World v;
  v.add_obstacle({"far", wall({4.0, 0.0}, 0.0), 0});
  v.add_obstacle({"slant", {c + 0.2 * t, c + 2.0 * t}, 0});
  v.finalize();
  SonarModel other(v, SonarParams{});
  const Echo e = other.trace({0.0, 0.0}, 0.0);
  ASSERT_TRUE(e.found);
  EXPECT_DOUBLE_EQ(e.range, 4.0);
}

// The nearer of two echoing surfaces wins.
TEST(Sonar, NearestEchoWins) {
  World w;
  w.add_obstacle({"far", wall({3.0, 0.0}, 0.0), 0});
  w.add_obstacle({"box", test::rect(1.5, 0.2, 1.7, 0.3), 0});  // 7.6° off axis
  w.finalize();
  SonarModel model(w, SonarParams{});
  const Echo e = model.trace({0.0, 0.0}, 0.0);
  ASSERT_TRUE(e.found);
  EXPECT_NEAR(e.range, std::hypot(1.5, 0.2), 1e-12);  // the box's nearest corner, face x = 1.5
}

// A T-junction of two walls 0.1 m thick: the west room's wall ends (squared off) inside the
// corridor's wall, flush with its face. Seen from the corridor at 68° to that face, the
// junction is a flat wall too oblique to echo; the end of the room's wall inside it is no
// surface. Before 2026-12-05 each polygon's edges were whole, and the end of the room wall's
// lower face echoed at 22° (the corner a ring sensor found on the building floor's corridors,
// docs/SIMULATOR.md).
TEST(Sonar, AFaceInsideAnotherSolidIsNoSurface) {
  World w;
  w.add_obstacle({"corridor wall", test::rect(-0.05, -5.0, 0.05, 5.0), 0});
  w.add_obstacle({"room wall", test::rect(-5.0, -0.05, 0.05, 0.05), 0});
  w.finalize();
  for (const Segment& sg : w.segments()) {  // no edge runs inside the other solid
    const Vec2 mid = 0.5 * (sg.a + sg.b);
    const auto& other = w.obstacles()[static_cast<std::size_t>(1 - sg.obstacle)].vertices;
    double off = 1.0;  // distance from the other solid's outline, m
    for (std::size_t k = 0; k < other.size(); ++k)
      off = std::min(off, point_segment_distance(mid, other[k], other[(k + 1) % other.size()]));
    EXPECT_FALSE(point_in_polygon(mid, other) && off > 1e-9)
        << "edge (" << sg.a.transpose() << ") - (" << sg.b.transpose() << ")";
  }
  SonarModel model(w, SonarParams{});
  const Vec2 o(0.45, -0.95);
  const Vec2 corner(0.05, -0.05);  // the room wall's end, on the corridor's face
  const Echo e = model.trace(o, std::atan2(corner.y() - o.y(), corner.x() - o.x()));
  EXPECT_FALSE(e.found) << "echo at " << e.range << " m off " << e.point.transpose();
  // The faces that are surfaces still echo: the corridor's face square on, the room wall's
  // lower face from the room's side.
  EXPECT_NEAR(model.trace({1.0, 2.0}, kPi).range, 0.95, 1e-12);
  EXPECT_NEAR(model.trace({-2.0, -1.0}, kPi / 2).range, 0.95, 1e-12);
  // Disjoint solids keep every edge.
  World d;
  d.add_obstacle({"a", test::rect(0.0, 0.0, 1.0, 1.0), 0});
  d.add_obstacle({"b", test::rect(2.0, 0.0, 3.0, 1.0), 0});
  d.finalize();
  EXPECT_EQ(d.segments().size(), 8u);
}

// Robot-mounted: sensor 1 sits on the front face, 0.695 m ahead of the axle.
TEST(Sonar, RingSensorOnTheRobot) {
  const World world = one_wall({3.0, 0.0}, 0.0);
  SonarModel model(world, default_ring_params());
  const RingLayout ring = default_ring_layout();
  EXPECT_NEAR(model.measure({1.0, 0.0, 0.0}, ring[0]), 2.0 - 0.695, 1e-12);
  // Turned round, sensor 13 (rear, 0.330 m behind the axle) faces the wall.
  EXPECT_NEAR(model.measure({1.0, 0.0, kPi}, ring[12]), 2.0 - 0.330, 1e-12);
  // Sensor 7 looks right: facing a wall on the right at 1.5 m from the axle.
  EXPECT_NEAR(model.measure({3.0 - 1.5, 0.0, kPi / 2}, ring[6]), 1.5 - 0.35, 1e-12);
}

// Seeded noise repeats; spurious echoes are never longer than the truth; drop-outs are silent;
// the calibration line applies to every reported range.
TEST(Sonar, SeededNoiseSpuriousEchoesAndDropouts) {
  const World world = one_wall({2.0, 0.0}, 0.0);
  SonarParams p;
  p.noise_sigma = 0.01;
  SonarModel model(world, p);
  Rng a(7), b(7);
  double sum = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double ra = model.measure_from({0.0, 0.0}, 0.0, &a);
    EXPECT_EQ(ra, model.measure_from({0.0, 0.0}, 0.0, &b));
    sum += ra;
  }
  EXPECT_NEAR(sum / 200, 2.0, 0.005);
  p = SonarParams{};
  p.spurious_probability = 1.0;
  model.set_params(p);
  for (int i = 0; i < 50; ++i) {
    const double r = model.measure_from({0.0, 0.0}, 0.0, &a);
    EXPECT_GE(r, p.min_range);
    EXPECT_LE(r, 2.0);
  }
  p = SonarParams{};
  p.dropout_probability = 1.0;
  model.set_params(p);
  EXPECT_EQ(model.measure_from({0.0, 0.0}, 0.0, &a), 0.0);
  EXPECT_EQ(model.measure_from({0.0, 0.0}, 0.0, nullptr), 2.0);  // no generator, no noise
  p = SonarParams{};
  p.scale = 0.96;
  p.offset = 0.043;
  model.set_params(p);
  EXPECT_NEAR(model.measure_from({0.0, 0.0}, 0.0), 0.96 * 2.0 + 0.043, 1e-12);
}

// The pan-tilt pair: 15 ms at 335 m/s = 2.5125 m; both sensors 5 cm from the pivot, back to
// back; raw readings follow the seed's measured line 0.96 · real + 43 mm.
TEST(PanTilt, BackToBackPairWithTheSeedsCalibration) {
  World w;
  w.add_obstacle({"east", wall({2.0, 0.0}, 0.0), 0});
  w.add_obstacle({"west", wall({-1.0, 0.0}, 0.0), 0});
  w.finalize();
  const SonarParams p = default_pan_tilt_params();
  EXPECT_NEAR(p.max_range(), 2.5125, 1e-12);
  SonarModel model(w, p);
  const PanTiltMount mount;  // pivot 0.030 m behind the axle
  const PanTiltReading r = measure_pan_tilt(model, {0.0, 0.0, 0.0}, mount, 0.0);
  const double east = 2.0 - (-0.030 + 0.05);
  const double west = (-0.030 - 0.05) + 1.0;
  EXPECT_NEAR(r.facing, 0.96 * east + 0.043, 1e-12);
  EXPECT_NEAR(r.opposite, 0.96 * west + 0.043, 1e-12);
  // Beyond 2.5125 m nothing comes back.
  const PanTiltReading far = measure_pan_tilt(model, {-0.62, 0.0, 0.0}, mount, 0.0);  // 2.62 m east, 0.30 m west
  EXPECT_EQ(far.facing, 0.0);
  EXPECT_GT(far.opposite, 0.0);
}

}  // namespace
}  // namespace robuter::sim

namespace robuter::sim {
namespace {

// A direct transcription of the model over every edge (no grid, no early exit), to check the
// fast tracer against on many random poses in a real world.
// Sets `borderline` when some edge's incidence is too close to the limit for the sampled
// reference to be trusted.
double brute_force_range(const World& w, const SonarParams& p, const Vec2& o, double dir,
                         bool& borderline) {
  borderline = false;
  struct C {
    double range;
    Vec2 point;
    bool echoes;
    int seg;
  };
  std::vector<C> cs;
  const double h = p.half_angle, rmax = p.max_range();
  for (std::size_t i = 0; i < w.segments().size(); ++i) {
    const Segment& sg = w.segments()[i];
    // Sample-free clipping: parametrise the edge and bisect where it enters/leaves the cone.
    const Vec2 ab = sg.b - sg.a;
    auto in_cone = [&](double t) {
      const Vec2 q = sg.a + t * ab - o;
      const double ang = std::atan2(q.y(), q.x()) - dir;
      return std::abs(wrap_angle(ang)) <= h + 1e-12 && q.norm() > 0.0;
    };
    // The in-cone part of a segment is one interval: a coarse scan, then a fine one around the
    // best coarse sample.
    double best_t = -1.0, best_r = 1e300;
    auto scan = [&](double from, double to, int n) {
      for (int k = 0; k <= n; ++k) {
        const double t = std::clamp(from + (to - from) * k / n, 0.0, 1.0);
        if (!in_cone(t)) continue;
        const double r = (sg.a + t * ab - o).norm();
        if (r < best_r) {
          best_r = r;
          best_t = t;
        }
      }
    };
    scan(0.0, 1.0, 400);
    if (best_t >= 0.0) scan(best_t - 1.0 / 400, best_t + 1.0 / 400, 400);
    if (best_t < 0.0 || best_r > rmax) continue;
    const Vec2 q = sg.a + best_t * ab - o;
    const Vec2 nrm(-ab.y(), ab.x());
    const double cosi = std::abs(nrm.dot(q)) / (nrm.norm() * q.norm());
    if (std::abs(cosi - std::cos(p.max_incidence)) < 2e-3) borderline = true;
    cs.push_back({best_r, sg.a + best_t * ab, cosi >= std::cos(p.max_incidence),
                  static_cast<int>(i)});
  }
  for (;;) {
    C* best = nullptr;
    for (auto& c : cs)
      if (c.echoes && (!best || c.range < best->range)) best = &c;
    if (!best) return 0.0;
    const Vec2 end = o + (best->range - 1e-6) * (best->point - o).normalized();
    bool hidden = false;
    for (const auto& c : cs) {
      if (c.echoes || c.range >= best->range) continue;
      if (segments_intersect(o, end, w.segments()[c.seg].a, w.segments()[c.seg].b)) hidden = true;
    }
    if (hidden) {
      best->echoes = false;
      continue;
    }
    return best->range < p.min_range ? 0.0 : best->range;
  }
}

// The grid walk with early exit agrees with the exhaustive model (to the brute force's 1 mm
// sampling) on random sensor poses in the default world.
TEST(Sonar, FastTracerAgreesWithExhaustiveSearch) {
  auto loaded = load_world(test::world_path("default.toml"));
  ASSERT_TRUE(loaded.ok());
  const World& w = loaded.value();
  SonarModel model(w, SonarParams{});
  Rng rng(2024);
  int echoes = 0;
  const int poses = robuter::test::sample(600, 120);  // the brute force is slow under the sanitizers
  for (int i = 0; i < poses; ++i) {
    const Vec2 o(rng.uniform(0.1, 7.9), rng.uniform(0.1, 5.9));
    const double dir = rng.uniform(-kPi, kPi);
    if (w.obstacle_containing(o) >= 0) continue;
    const double fast = model.measure_from(o, dir);
    bool borderline = false;
    const double slow = brute_force_range(w, SonarParams{}, o, dir, borderline);
    if (borderline) continue;
    if (fast > 0.0) ++echoes;
    EXPECT_NEAR(fast, slow, 2e-3) << "origin " << o.transpose() << " direction " << dir;
  }
  EXPECT_GT(echoes, poses * 350 / 600);
}

}  // namespace
}  // namespace robuter::sim
