// Pictures of the simulated world with cairo: obstacles, doors, robot and trail, sonar beams
// and pan-tilt rays, to PNG or SVG through one renderer, with hooks for maps and paths.
#pragma once

#include <cairo.h>

#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hal/sim/footprint.hpp"
#include "hal/sim/result.hpp"
#include "hal/sim/sonar_layout.hpp"
#include "hal/sim/trail.hpp"

namespace robuter::sim {

// World-to-picture mapping: metres to device units (pixels for PNG, points for SVG), y up.
struct View {
  Box world{Vec2::Zero(), Vec2::Zero()};  // world area shown, m
  double scale = 60.0;                    // device units per metre
  int width = 0;                          // picture width, device units
  int height = 0;                         // picture height, device units

  // Device coordinates of a world point.
  Vec2 to_device(const Vec2& w) const {
    return {(w.x() - world.lo.x()) * scale, (world.hi.y() - w.y()) * scale};
  }
  // Sets the context's transform so that user units are world metres (y up); line widths set
  // afterwards are in metres too.
  void apply(cairo_t* cr) const;
};

// One sonar beam to draw, already in the world frame.
struct SonarBeam {
  Vec2 origin;             // transducer position, m
  double direction = 0.0;  // beam axis, rad
  double half_angle = 0.0; // cone half-angle, rad
  double range = 0.0;      // reported range, m (0: no echo)
  double max_range = 0.0;  // time-out range, m
  int number = 0;          // sensor number to label (0: none)
};

// Something extra to draw; the context is in device units when it is called.
using DrawHook = std::function<void(cairo_t*, const View&)>;

// What to draw. Pointers may be null; the world must outlive rendering.
struct Scene {
  const World* world = nullptr;          // obstacles, doors, start, goal, markers
  RobotGeometry geometry;                // body to draw
  std::optional<Pose> robot;             // true pose of the robot, if drawn
  const Trail* trail = nullptr;          // where the robot has been
  std::vector<SonarBeam> beams;          // ring beams with their ranges
  std::vector<SonarBeam> pan_tilt;       // pan-tilt rays with their ranges
  DrawHook underlay;                     // e.g. an occupancy map: drawn under the obstacles
  DrawHook overlay;                      // e.g. a planned path: drawn on top of everything
  std::string title;                     // caption in the top-left corner
};

// How to draw it.
struct RenderOptions {
  double pixels_per_metre = 60.0;  // scale, device units per metre
  double margin = 0.4;             // space around the content, m
  bool grid = true;                // light 1 m grid
  bool labels = true;              // names of doors and markers, sensor numbers
  bool cones = true;               // beam cones (else only the axis to the echo)
};

// Picks the world area (obstacles, robot, trail, start, goal, plus margin) and the scale.
View make_view(const Scene& scene, const RenderOptions& options);

// Draws the scene on any cairo context (the one renderer behind both file formats).
void render(cairo_t* cr, const Scene& scene, const View& view, const RenderOptions& options);

// Writes the scene as a PNG file.
Status render_png(const Scene& scene, const RenderOptions& options,
                  const std::filesystem::path& path);

// Writes the scene as an SVG file.
Status render_svg(const Scene& scene, const RenderOptions& options,
                  const std::filesystem::path& path);

// Frees cairo's and fontconfig's process-wide caches (text drawing fills them). Call once at
// the end of a program or test run checked by LeakSanitizer; render nothing afterwards.
void release_render_caches();

// Beams for every ring sensor of a robot at `robot`, given their reported ranges (entry i for
// sensor i + 1).
std::vector<SonarBeam> ring_beams(const Pose& robot, const RingLayout& layout,
                                  std::span<const double, kRingSensors> ranges,
                                  const SonarParams& params);

// The two pan-tilt beams for a firing with the first sensor looking along `direction`.
std::vector<SonarBeam> pan_tilt_beams(const Pose& robot, const PanTiltMount& mount,
                                      double direction, const PanTiltReading& reading,
                                      const SonarParams& params);

}  // namespace robuter::sim
