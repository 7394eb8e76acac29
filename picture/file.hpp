// SPDX-License-Identifier: GPL-3.0-or-later
// A page's file: a PNG, SVG or PDF surface by the path's extension, drawn by a callback, written or refused.
#pragma once

#include <cairo.h>

#include <functional>
#include <optional>
#include <string>

namespace robuter::picture {

// The file formats a page can be written in.
enum class Format { png, svg, pdf, none };

// The format named by a path's extension (.png, .svg, .pdf, any case); none for anything else.
Format format_of(const std::string& path);

// Makes a `width` × `height` surface of `format` for `path`, lets `draw` draw on it, and writes
// it (PNG, SVG in points, PDF in points with its words kept as text); why not, or nothing.
std::optional<std::string> write_page(const std::string& path, Format format, int width, int height,
                                      const std::function<void(cairo_t*)>& draw);

}  // namespace robuter::picture
