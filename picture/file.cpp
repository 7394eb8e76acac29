// SPDX-License-Identifier: GPL-3.0-or-later
// Writing a page as PNG (image surface), SVG or PDF (vector surfaces) with cairo.
#include "picture/file.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace robuter::picture {

Format format_of(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e == ".png" ? Format::png : e == ".svg" ? Format::svg : e == ".pdf" ? Format::pdf : Format::none;
}

std::optional<std::string> write_page(const std::string& path, Format format, int width, int height,
                                      const std::function<void(cairo_t*)>& draw) {
  cairo_surface_t* surface = nullptr;
  switch (format) {
    case Format::png: surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height); break;
    case Format::svg: surface = cairo_svg_surface_create(path.c_str(), width, height); break;
    case Format::pdf: surface = cairo_pdf_surface_create(path.c_str(), width, height); break;
    case Format::none: return std::string("expected a .png, .svg or .pdf file");
  }
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
    const std::string why = cairo_status_to_string(cairo_surface_status(surface));
    cairo_surface_destroy(surface);
    return "cannot write the picture: " + why;
  }
  cairo_t* cr = cairo_create(surface);
  draw(cr);
  cairo_destroy(cr);
  cairo_status_t st = CAIRO_STATUS_SUCCESS;
  if (format == Format::png) {
    st = cairo_surface_write_to_png(surface, path.c_str());
  } else {
    cairo_surface_finish(surface);
    st = cairo_surface_status(surface);
  }
  cairo_surface_destroy(surface);
  if (st != CAIRO_STATUS_SUCCESS) return std::string("cannot write the picture: ") + cairo_status_to_string(st);
  return std::nullopt;
}

}  // namespace robuter::picture
