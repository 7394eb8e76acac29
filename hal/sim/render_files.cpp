// SPDX-License-Identifier: GPL-3.0-or-later
// The picture's page (world area, scale, size), its files (PNG, SVG, PDF) and the beams to draw.
#include <limits>

#include "hal/sim/render.hpp"
#include "picture/file.hpp"
#include "picture/page.hpp"

namespace robuter::sim {

namespace {

// Enlarges a box to contain a point.
void grow(Box& b, const Vec2& p) {
  b.lo = b.lo.cwiseMin(p);
  b.hi = b.hi.cwiseMax(p);
}

// Shared by every format: the page make_view picks, drawn and written by picture::write_page.
Result<picture::Layout> write(const Scene& scene, const RenderOptions& options, const std::filesystem::path& path,
                              picture::Format format) {
  const View v = make_view(scene, options);
  picture::Layout layout;
  const auto why = picture::write_page(path.string(), format, v.width, v.height,
                                       [&](cairo_t* cr) { layout = render(cr, scene, v, options); });
  if (why) return Error{path.string(), 0, *why};
  return layout;
}

}  // namespace

// Everything that will be drawn contributes to the bounds.
View make_view(const Scene& scene, const RenderOptions& options) {
  Box b{Vec2::Constant(std::numeric_limits<double>::infinity()),
        Vec2::Constant(-std::numeric_limits<double>::infinity())};
  if (scene.world != nullptr) {
    const World& w = *scene.world;
    if (!w.segments().empty()) {
      grow(b, w.bounds().lo);
      grow(b, w.bounds().hi);
    }
    if (w.start) grow(b, {w.start->x, w.start->y});
    if (w.goal) grow(b, *w.goal);
    for (const auto& m : w.markers) grow(b, {m.pose.x, m.pose.y});
  }
  if (scene.robot) {
    Vec2 c[4];
    footprint_corners(scene.geometry, *scene.robot, c);
    for (const auto& p : c) grow(b, p);
  }
  if (scene.trail != nullptr) {
    for (std::size_t i = 0; i < scene.trail->size(); ++i) grow(b, (*scene.trail)[i]);
  }
  if (!(b.lo.x() <= b.hi.x())) b = {Vec2(-1, -1), Vec2(1, 1)};
  picture::FrameOptions page;
  page.pixels_per_metre = options.pixels_per_metre;
  page.min_width = options.min_width;
  return picture::make_frame(b.lo - Vec2::Constant(options.margin), b.hi + Vec2::Constant(options.margin), page);
}

Result<picture::Layout> render_png(const Scene& scene, const RenderOptions& options,
                                   const std::filesystem::path& path) {
  return write(scene, options, path, picture::Format::png);
}

Result<picture::Layout> render_svg(const Scene& scene, const RenderOptions& options,
                                   const std::filesystem::path& path) {
  return write(scene, options, path, picture::Format::svg);
}

Result<picture::Layout> render_pdf(const Scene& scene, const RenderOptions& options,
                                   const std::filesystem::path& path) {
  return write(scene, options, path, picture::Format::pdf);
}

Result<picture::Layout> render_file(const Scene& scene, const RenderOptions& options,
                                    const std::filesystem::path& path) {
  return write(scene, options, path, picture::format_of(path.string()));
}

bool picture_format_ok(const std::filesystem::path& path) {
  return picture::format_of(path.string()) != picture::Format::none;
}

void release_render_caches() { picture::release_caches(); }

// Mount positions moved into the world; ranges as reported (the ring is uncalibrated).
std::vector<SonarBeam> ring_beams(const Pose& robot, const RingLayout& layout,
                                  std::span<const double, kRingSensors> ranges,
                                  const SonarParams& params) {
  std::vector<SonarBeam> out;
  out.reserve(kRingSensors);
  for (int i = 0; i < kRingSensors; ++i) {
    SonarBeam b;
    sensor_in_world(robot, layout[i], b.origin, b.direction);
    b.half_angle = params.half_angle;
    b.range = ranges[i];
    b.max_range = params.max_range();
    b.number = layout[i].number;
    out.push_back(b);
  }
  return out;
}

// Reported pan-tilt readings are raw: undo the calibration line to draw true distances.
std::vector<SonarBeam> pan_tilt_beams(const Pose& robot, const PanTiltMount& mount,
                                      double direction, const PanTiltReading& reading,
                                      const SonarParams& params) {
  const auto m = pan_tilt_mounts(mount, direction);
  std::vector<SonarBeam> out(2);
  const double r[2] = {reading.facing, reading.opposite};
  for (int i = 0; i < 2; ++i) {
    sensor_in_world(robot, m[i], out[i].origin, out[i].direction);
    out[i].half_angle = params.half_angle;
    out[i].range = (r[i] > 0.0 && r[i] != params.no_echo) ? (r[i] - params.offset) / params.scale : 0.0;
    out[i].max_range = params.max_range();
  }
  return out;
}

}  // namespace robuter::sim
