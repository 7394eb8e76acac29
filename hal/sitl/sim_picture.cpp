// The robuterd --picture scene: built from the SimRobot and the ranges the firmware last read.
#include "hal/sitl/sim_picture.hpp"

#include <array>
#include <cstdio>

namespace robuter::hal {

namespace {
// Lower-case extension of `path` ("" if none); why: the picture format follows it.
std::string extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string e = path.substr(dot + 1);
  for (char& c : e) c = static_cast<char>((c >= 'A' && c <= 'Z') ? c - 'A' + 'a' : c);
  return e;
}
}  // namespace

// Why at start-up: a typo must not cost a whole run whose picture is then not written.
bool picture_path_ok(const std::string& path) {
  const std::string e = extension(path);
  return e == "png" || e == "svg";
}

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

// Why a title with the time: pictures of several runs are told apart at a glance.
std::optional<std::string> write_sim_picture(const SimRobot& r,
                                             std::span<const std::uint16_t, kRingSensors> mm,
                                             std::uint32_t no_echo, const std::string& path) {
  if (!picture_path_ok(path)) return "picture " + path + ": expected a .png or .svg file";
  char title[160];
  std::snprintf(title, sizeof title, "robuterd: %s after %.1f s", r.world().name.c_str(), r.time());
  const sim::Scene scene = sim_scene(r, mm, no_echo, title);
  const sim::Status s = extension(path) == "svg" ? sim::render_svg(scene, sim::RenderOptions{}, path)
                                                 : sim::render_png(scene, sim::RenderOptions{}, path);
  if (!s) return "picture: " + s.error().describe();
  return std::nullopt;
}

// Why a wrapper: robuterd need not include the renderer to release its caches.
void release_picture_caches() { sim::release_render_caches(); }

}  // namespace robuter::hal
