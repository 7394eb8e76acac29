// SPDX-License-Identifier: GPL-3.0-or-later
// Pictures of the simulated world with cairo: obstacles, doors, robot and trail, sonar beams and
// pan-tilt rays, with title, axes, scale bar and legend, to PNG, SVG or PDF through one renderer.
#pragma once

#include <cairo.h>

#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hal/sim/footprint.hpp"
#include "picture/frame.hpp"
#include "picture/layout.hpp"
#include "picture/legend.hpp"
#include "hal/sim/result.hpp"
#include "hal/sim/sonar_layout.hpp"
#include "hal/sim/trail.hpp"

namespace robuter::sim {

// World-to-picture mapping: the plot area (metres, y up) on a page with room for the title, the
// axes, the scale bar and the legend (picture/frame.hpp).
using View = picture::Frame;

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
  std::vector<picture::Ink> keys;        // legend entries for what the hooks draw
  std::string title;                     // what, when, outcome (default: the world's name)
};

// How to draw it.
struct RenderOptions {
  double pixels_per_metre = 0.0;   // scale, device units per metre; 0 = fill min_width
  int min_width = 1000;            // the picture is at least this wide, device units
  double margin = 0.4;             // space around the content, m
  bool grid = true;                // light 1 m grid
  bool labels = true;              // names of doors and markers, sensor numbers
  bool cones = true;               // beam cones (else only the axis to the echo)
};

// Picks the world area (obstacles, robot, trail, start, goal, plus margin), the scale and the page.
View make_view(const Scene& scene, const RenderOptions& options);

// Draws the scene on any cairo context (the one renderer behind every file format); what it laid
// out: title, legend entries, scale bar, axis labels, text labels, with their boxes.
picture::Layout render(cairo_t* cr, const Scene& scene, const View& view, const RenderOptions& options);

// Writes the scene as a PNG file; what was laid out.
Result<picture::Layout> render_png(const Scene& scene, const RenderOptions& options,
                                   const std::filesystem::path& path);

// Writes the scene as an SVG file; what was laid out.
Result<picture::Layout> render_svg(const Scene& scene, const RenderOptions& options,
                                   const std::filesystem::path& path);

// Writes the scene as a PDF file (its words are text a PDF reader can extract); what was laid out.
Result<picture::Layout> render_pdf(const Scene& scene, const RenderOptions& options,
                                   const std::filesystem::path& path);

// Writes the scene in the format named by the path's extension (.png, .svg or .pdf).
Result<picture::Layout> render_file(const Scene& scene, const RenderOptions& options,
                                    const std::filesystem::path& path);

// True when the path ends in .png, .svg or .pdf (any case): a format render_file writes.
bool picture_format_ok(const std::filesystem::path& path);

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
