// SPDX-License-Identifier: GPL-3.0-or-later
// The robuterd --picture scene: built from the SimRobot and the ranges the firmware last read.
#include "hal/sitl/sim_picture.hpp"

#include <array>
#include <cstdio>

#include "picture/page.hpp"

namespace robuter::hal {

// Why at start-up: a typo must not cost a whole run whose picture is then not written.
bool picture_path_ok(const std::string& path) { return sim::picture_format_ok(path); }

// Why the true pose: the picture shows where the robot is, not where its odometry thinks.
sim::Scene sim_scene(const SimRobot& r, std::span<const std::uint16_t, kRingSensors> mm,
                     std::uint32_t no_echo, const std::string& title) {
  sim::Scene scene;
  scene.world = &r.world();
  scene.geometry = r.robot().params().geometry;
  scene.robot = r.robot().pose();
  scene.trail = &r.robot().trail();
  std::array<double, sim::kRingSensors> ranges{};
  for (std::size_t i = 0; i < ranges.size(); ++i)
    ranges[i] = (no_echo & (1u << i)) ? 0.0 : mm[i] / 1000.0;
  scene.beams = sim::ring_beams(r.robot().pose(), r.layout(), ranges, r.ring_params());
  const PanTiltShot& shot = r.last_pan_tilt();
  if (shot.valid) {
    // Index 1 looks along angle + 90°: the "facing" sensor of measure_pan_tilt.
    const sim::PanTiltReading reading{shot.mm[1] / 1000.0, shot.mm[0] / 1000.0};
    scene.pan_tilt = sim::pan_tilt_beams(r.robot().pose(), r.pan_tilt_mount(),
                                         SimRobot::pan_tilt_direction(shot.angle_deg), reading,
                                         r.pan_tilt_params());
  }
  scene.title = title;
  return scene;
}

// Why this title: what (world), when (simulated seconds, the date), outcome (where the robot
// ended, how far it went, the emergency) — pictures of several runs are told apart at a glance.
sim::Result<picture::Layout> write_sim_picture(const SimRobot& r,
                                             std::span<const std::uint16_t, kRingSensors> mm,
                                             std::uint32_t no_echo, const std::string& outcome,
                                             const std::string& path) {
  if (!picture_path_ok(path)) return sim::Error{path, 0, "expected a .png, .svg or .pdf file"};
  const sim::Trail& t = r.robot().trail();
  double travelled = 0.0;
  for (std::size_t i = 1; i < t.size(); ++i) travelled += (t[i] - t[i - 1]).norm();
  const sim::Pose& p = r.robot().pose();
  char title[320];
  std::snprintf(title, sizeof title, "robuterd --sim, %s, after %.1f s (%s): travelled %.2f m, at (%.2f m, %.2f m, %.0f deg)%s; %s",
                r.world().name.c_str(), r.time(), picture::utc_now().c_str(), travelled, p.x, p.y,
                p.theta * 180.0 / 3.14159265358979, r.robot().bumper() ? ", bumper pressed" : "", outcome.c_str());
  const sim::Scene scene = sim_scene(r, mm, no_echo, title);
  return sim::render_file(scene, sim::RenderOptions{}, path);
}

// Why a wrapper: robuterd need not include the renderer to release its caches.
void release_picture_caches() { sim::release_render_caches(); }

}  // namespace robuter::hal
