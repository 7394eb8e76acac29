// SPDX-License-Identifier: GPL-3.0-or-later
// The crossing picture: the simulator's renderer with the scans drawn on top (overlay hook) and named in its legend.
#include "tools/robuter-doors-run/crossing_picture.hpp"

#include <cairo.h>

#include <cmath>
#include <numbers>

#include "hal/sim/render.hpp"
#include "picture/page.hpp"

namespace robuter::test {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr int kNoEchoMm = 2546;  // the corrected cap: no echo (docs/PROTOCOL.md, BP)

// A ray of one sector in the world: from the transducer face to where it reported, m.
struct Ray {
  sim::Vec2 from, to;
  bool echo = false;  // false: nothing within the cap
};

// Why through the snapshot's odometry/truth pair: the scan's sector poses are odometry; with
// exact odometry the same rigid transform places every one of them in the world.
Ray sector_ray(const ScanSnapshot& s, int i, const Config& cfg) {
  const SectorPose& p = s.scan.pose[static_cast<std::size_t>(i)];
  const double oth = s.odometry.theta * 0.01 * kPi / 180.0;
  const double rot = s.truth.theta - oth;
  auto to_world = [&](double x, double y) {  // odometry frame, m → world, m
    const double dx = x - s.odometry.x * 1e-4, dy = y - s.odometry.y * 1e-4;
    return sim::Vec2{s.truth.x + dx * std::cos(rot) - dy * std::sin(rot), s.truth.y + dx * std::sin(rot) + dy * std::cos(rot)};
  };
  const double h = p.theta * 0.01 * kPi / 180.0;
  const double ax = p.x * 1e-4 + cfg.ptu.pivot_x_mm * 1e-3 * std::cos(h), ay = p.y * 1e-4 + cfg.ptu.pivot_x_mm * 1e-3 * std::sin(h);
  const double a = h + s.scan.direction[static_cast<std::size_t>(i)] * 0.01 * kPi / 180.0;
  const double face = robot_model(cfg).pan_tilt.face_offset;
  const int raw = s.scan.raw[static_cast<std::size_t>(i)];
  const double range = face + raw * 1e-3;
  Ray r;
  r.from = to_world(ax + face * std::cos(a), ay + face * std::sin(a));
  r.to = to_world(ax + range * std::cos(a), ay + range * std::sin(a));
  r.echo = raw < kNoEchoMm;
  return r;
}

// One ink per snapshot (blue, orange, green, purple), named by its label.
picture::Ink snapshot_ink(std::size_t k, const std::string& label) {
  static constexpr picture::Rgb kColours[] = {{0.10, 0.35, 0.85}, {0.90, 0.45, 0.05}, {0.10, 0.60, 0.20}, {0.55, 0.20, 0.70}};
  return {kColours[k % 4], picture::Swatch::line, label + ": rays, dots at echoes", 1.0, 2.0};
}
}  // namespace

// Why an overlay rather than Scene::pan_tilt: several scans, each in its own colour, named in the legend.
sim::Result<picture::Layout> write_crossing_picture(const hal::SimRobot& r, const Config& cfg,
                                                   std::span<const ScanSnapshot> snaps, const std::string& title,
                                                   const std::string& path) {
  sim::Scene scene;
  scene.world = &r.world();
  scene.geometry = r.robot().params().geometry;
  scene.robot = r.robot().pose();
  scene.trail = &r.robot().trail();
  scene.title = "door crossing, " + title + ", " + picture::utc_now();
  for (std::size_t k = 0; k < snaps.size(); ++k) scene.keys.push_back(snapshot_ink(k, snaps[k].label));
  scene.overlay = [&](cairo_t* cr, const sim::View& view) {
    for (std::size_t k = 0; k < snaps.size(); ++k) {
      const picture::Rgb c = scene.keys[k].colour;
      cairo_set_line_width(cr, 1.0);
      for (int i = 0; i < kPanTiltSectors; ++i) {
        if (snaps[k].scan.read_tick[static_cast<std::size_t>(i)] == 0) continue;
        const Ray ray = sector_ray(snaps[k], i, cfg);
        const sim::Vec2 a = view.to_device(ray.from), b = view.to_device(ray.to);
        cairo_set_source_rgba(cr, c.r, c.g, c.b, ray.echo ? 0.45 : 0.18);
        cairo_move_to(cr, a.x(), a.y());
        cairo_line_to(cr, b.x(), b.y());
        cairo_stroke(cr);
        if (ray.echo) {
          cairo_set_source_rgb(cr, c.r, c.g, c.b);
          cairo_arc(cr, b.x(), b.y(), 2.5, 0.0, 2.0 * kPi);
          cairo_fill(cr);
        }
      }
    }
  };
  sim::RenderOptions options;
  auto laid = sim::render_file(scene, options, path);
  if (!laid) return sim::Error{path, 0, "picture " + path + ": " + laid.error().describe()};
  return laid;
}

}  // namespace robuter::test
