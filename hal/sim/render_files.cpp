// The picture's page (world area, scale, size), its files (PNG, SVG, PDF) and the beams to draw.
#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <algorithm>
#include <cctype>
#include <limits>

#include "hal/sim/render.hpp"
#include "picture/page.hpp"

namespace robuter::sim {

namespace {

// Enlarges a box to contain a point.
void grow(Box& b, const Vec2& p) {
  b.lo = b.lo.cwiseMin(p);
  b.hi = b.hi.cwiseMax(p);
}

// The file formats, by lower-case extension.
enum class Format { png, svg, pdf, none };
Format format_of(const std::filesystem::path& path) {
  std::string e = path.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e == ".png" ? Format::png : e == ".svg" ? Format::svg : e == ".pdf" ? Format::pdf : Format::none;
}

// Shared by every format: draws on the surface, finishes it, reports cairo's status.
Result<picture::Layout> finish_surface(cairo_surface_t* surface, const Scene& scene, const View& view,
                                       const RenderOptions& options, const std::filesystem::path& path, bool png) {
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
    const std::string why = cairo_status_to_string(cairo_surface_status(surface));
    cairo_surface_destroy(surface);
    return Error{path.string(), 0, "cannot write the picture: " + why};
  }
  cairo_t* cr = cairo_create(surface);
  picture::Layout layout = render(cr, scene, view, options);
  cairo_destroy(cr);
  cairo_status_t st = CAIRO_STATUS_SUCCESS;
  if (png) {
    st = cairo_surface_write_to_png(surface, path.string().c_str());
  } else {
    cairo_surface_finish(surface);
    st = cairo_surface_status(surface);
  }
  cairo_surface_destroy(surface);
  if (st != CAIRO_STATUS_SUCCESS) {
    return Error{path.string(), 0, std::string("cannot write the picture: ") + cairo_status_to_string(st)};
  }
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

// An ARGB image surface sized by make_view, written with cairo's PNG writer.
Result<picture::Layout> render_png(const Scene& scene, const RenderOptions& options,
                                   const std::filesystem::path& path) {
  const View v = make_view(scene, options);
  return finish_surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, v.width, v.height), scene, v, options,
                        path, true);
}

// A vector picture of the same drawing, units = points.
Result<picture::Layout> render_svg(const Scene& scene, const RenderOptions& options,
                                   const std::filesystem::path& path) {
  const View v = make_view(scene, options);
  return finish_surface(cairo_svg_surface_create(path.string().c_str(), v.width, v.height), scene, v, options,
                        path, false);
}

// The same drawing as one PDF page, units = points; its words stay text.
Result<picture::Layout> render_pdf(const Scene& scene, const RenderOptions& options,
                                   const std::filesystem::path& path) {
  const View v = make_view(scene, options);
  return finish_surface(cairo_pdf_surface_create(path.string().c_str(), v.width, v.height), scene, v, options,
                        path, false);
}

Result<picture::Layout> render_file(const Scene& scene, const RenderOptions& options,
                                    const std::filesystem::path& path) {
  switch (format_of(path)) {
    case Format::png: return render_png(scene, options, path);
    case Format::svg: return render_svg(scene, options, path);
    case Format::pdf: return render_pdf(scene, options, path);
    case Format::none: break;
  }
  return Error{path.string(), 0, "expected a .png, .svg or .pdf file"};
}

bool picture_format_ok(const std::filesystem::path& path) { return format_of(path) != Format::none; }

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
