// SPDX-License-Identifier: GPL-3.0-or-later
// Seed 003's local grid per place: cutting it from the map, its text form, files, applying it.
#include "modules/places/place_grid.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <system_error>

#include "modules/planner/lib/text_reader.hpp"

namespace robuter::places {

namespace {

constexpr int kMaxSide = 8192;  // cells per side a grid file may hold (a 400 m place at 5 cm)

// Why: the shortest text that reads back as the same double.
std::string real_text(double v) {
  std::array<char, 32> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  return std::string(buf.data(), r.ptr);
}

// Why: place names as the place graph's file allows them (letters, digits, '-', '_').
bool name_ok(std::string_view s) {
  if (s.empty() || s.size() > 63) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
  });
}

}  // namespace

PlaceBox place_box(const PlaceGraph& graph, std::size_t place, const plan::MapGeometry& map, double margin) {
  const Place& p = graph.places().at(place);
  double x0 = p.area.front().x(), x1 = x0, y0 = p.area.front().y(), y1 = y0;
  for (const Vec2& v : p.area) {
    x0 = std::min(x0, v.x());
    x1 = std::max(x1, v.x());
    y0 = std::min(y0, v.y());
    y1 = std::max(y1, v.y());
  }
  margin = std::max(margin, 0.0);
  const double r = map.resolution;
  // Every cell the box touches; a box edge exactly on a cell boundary takes no cell beyond it.
  const double eps = 1e-9 * r;
  auto cell = [&](double v, double o) {
    const double c = std::floor((v - o) / r);
    return c > -1e9 && c < 1e9 ? static_cast<int>(c) : 0;  // places and maps are finite and small
  };
  const plan::Cell lo{cell(x0 - margin + eps, map.origin.x), cell(y0 - margin + eps, map.origin.y)};
  const plan::Cell hi{cell(x1 + margin - eps, map.origin.x), cell(y1 + margin - eps, map.origin.y)};
  PlaceBox b;
  b.lo = lo;
  b.width = std::max(1, hi.x - lo.x + 1);
  b.height = std::max(1, hi.y - lo.y + 1);
  // Rounded to the nanometre: the file then says -0.05, not -0.04999999999999938.
  auto nm = [](double v) { return std::round(v * 1e9) / 1e9; };
  b.origin = {nm(map.origin.x + lo.x * r), nm(map.origin.y + lo.y * r)};
  return b;
}

bool cut_place_into(const PlaceGraph& graph, std::size_t place, const plan::OccupancyMap& map,
                    std::optional<plan::Point2> robot, PlaceGrid& out, double margin) {
  const PlaceBox b = place_box(graph, place, map.geometry(), margin);
  const std::size_t n = static_cast<std::size_t>(b.width) * static_cast<std::size_t>(b.height);
  if (n > out.cells.capacity()) return false;
  out.cell = map.resolution();
  out.width = b.width;
  out.height = b.height;
  out.origin = b.origin;
  out.scanned_from.reset();
  out.cells.assign(n, plan::CellState::Unknown);
  for (int y = 0; y < b.height; ++y)
    for (int x = 0; x < b.width; ++x) {
      const plan::Cell c{b.lo.x + x, b.lo.y + y};
      if (map.contains(c))
        out.cells[static_cast<std::size_t>(y) * static_cast<std::size_t>(b.width) + static_cast<std::size_t>(x)] =
            map.state(c);
    }
  if (robot) {
    const plan::Cell c = map.cell_of(*robot);
    if (c.x >= b.lo.x && c.x < b.lo.x + b.width && c.y >= b.lo.y && c.y < b.lo.y + b.height) {
      out.scanned_from = plan::Cell{c.x - b.lo.x, c.y - b.lo.y};
      // The robot stands there: the cell is free (as 'P' reads back).
      out.cells[static_cast<std::size_t>(c.y - b.lo.y) * static_cast<std::size_t>(b.width) +
                static_cast<std::size_t>(c.x - b.lo.x)] = plan::CellState::Free;
    }
  }
  return true;
}

PlaceGrid cut_place(const PlaceGraph& graph, std::size_t place, const plan::OccupancyMap& map,
                    std::optional<plan::Point2> robot, double margin) {
  const PlaceBox b = place_box(graph, place, map.geometry(), margin);
  PlaceGrid g;
  g.place = graph.places().at(place).name;
  g.cells.reserve(static_cast<std::size_t>(b.width) * static_cast<std::size_t>(b.height));
  cut_place_into(graph, place, map, robot, g, margin);
  return g;
}

std::string place_grid_text(const PlaceGrid& g) {
  std::string out;
  out += "# robuter place grid: seed 003's characters, '.' unknown, '#' obstacle, ' ' free, 'P' the robot\n";
  out += "place " + g.place + "\n";
  out += "cell " + real_text(g.cell) + "\n";
  out += "origin " + real_text(g.origin.x) + " " + real_text(g.origin.y) + "\n";
  out += "size " + std::to_string(g.width) + " " + std::to_string(g.height) + "\n";
  if (g.scanned_from)
    out += "scanned " + std::to_string(g.scanned_from->x) + " " + std::to_string(g.scanned_from->y) + "\n";
  else
    out += "scanned none\n";
  out += "grid\n";
  out.reserve(out.size() + static_cast<std::size_t>(g.width + 1) * static_cast<std::size_t>(g.height));
  for (int y = g.height - 1; y >= 0; --y) {
    for (int x = 0; x < g.width; ++x) {
      if (g.scanned_from && g.scanned_from->x == x && g.scanned_from->y == y) {
        out += 'P';
        continue;
      }
      switch (g.at(x, y)) {
        case plan::CellState::Unknown: out += '.'; break;
        case plan::CellState::Occupied: out += '#'; break;
        case plan::CellState::Free: out += ' '; break;
      }
    }
    out += '\n';
  }
  return out;
}

plan::Result<PlaceGrid> parse_place_grid(std::string_view text, const std::string& file) {
  const std::vector<std::string_view> lines = plan::split_lines(text);
  auto error = [&](std::size_t line, std::string message) {
    return plan::Error{file, static_cast<int>(line + 1), std::move(message)};
  };
  PlaceGrid g;
  bool have_place = false, have_cell = false, have_origin = false, have_size = false, have_scanned = false;
  std::optional<plan::Cell> p_cell;
  std::size_t i = 0;
  for (; i < lines.size(); ++i) {
    const std::string_view line = lines[i];
    if (line.empty() || line.front() == '#') continue;
    const std::vector<std::string_view> w = plan::split_words(line);
    if (w.empty()) continue;
    if (w[0] == "grid") {
      if (w.size() != 1) return error(i, "'grid' takes nothing after it");
      break;
    }
    auto once = [&](bool& seen) -> std::optional<plan::Error> {
      if (seen) return error(i, "'" + std::string(w[0]) + "' given twice");
      seen = true;
      return std::nullopt;
    };
    auto count = [&](std::size_t n) -> std::optional<plan::Error> {
      if (w.size() != n + 1)
        return error(i, "'" + std::string(w[0]) + "' takes " + std::to_string(n) + (n == 1 ? " value" : " values"));
      return std::nullopt;
    };
    if (w[0] == "place") {
      if (auto e = once(have_place)) return *e;
      if (auto e = count(1)) return *e;
      if (!name_ok(w[1])) return error(i, "place name '" + std::string(w[1]) + "': letters, digits, '-', '_'");
      g.place = std::string(w[1]);
    } else if (w[0] == "cell") {
      if (auto e = once(have_cell)) return *e;
      if (auto e = count(1)) return *e;
      const auto v = plan::parse_real(w[1]);
      if (!v || !(*v > 0.0) || *v > 10.0) return error(i, "cell: a side in metres, above 0 and at most 10");
      g.cell = *v;
    } else if (w[0] == "origin") {
      if (auto e = once(have_origin)) return *e;
      if (auto e = count(2)) return *e;
      const auto x = plan::parse_real(w[1]), y = plan::parse_real(w[2]);
      if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y) || std::abs(*x) > 1e6 || std::abs(*y) > 1e6)
        return error(i, "origin: two coordinates in metres");
      g.origin = {*x, *y};
    } else if (w[0] == "size") {
      if (auto e = once(have_size)) return *e;
      if (auto e = count(2)) return *e;
      const auto x = plan::parse_integer(w[1]), y = plan::parse_integer(w[2]);
      if (!x || !y || *x < 1 || *y < 1 || *x > kMaxSide || *y > kMaxSide)
        return error(i, "size: columns and rows, whole numbers from 1 to " + std::to_string(kMaxSide));
      g.width = static_cast<int>(*x);
      g.height = static_cast<int>(*y);
    } else if (w[0] == "scanned") {
      if (auto e = once(have_scanned)) return *e;
      if (w.size() == 2 && w[1] == "none") continue;
      if (auto e = count(2)) return *e;
      const auto x = plan::parse_integer(w[1]), y = plan::parse_integer(w[2]);
      if (!x || !y || *x < 0 || *y < 0 || *x >= kMaxSide || *y >= kMaxSide)
        return error(i, "scanned: a cell (column, row from the south-west corner) or 'none'");
      p_cell = plan::Cell{static_cast<int>(*x), static_cast<int>(*y)};
    } else {
      return error(i, "unknown key '" + std::string(w[0]) + "' (place, cell, origin, size, scanned, grid)");
    }
  }
  if (i == lines.size()) return plan::Error{file, static_cast<int>(lines.size()), "no 'grid' line: the rows are missing"};
  for (const auto& [seen, key] : {std::pair{have_place, "place"}, std::pair{have_cell, "cell"},
                                  std::pair{have_origin, "origin"}, std::pair{have_size, "size"},
                                  std::pair{have_scanned, "scanned"}})
    if (!seen) return error(i, std::string("'") + key + "' is missing before 'grid'");
  if (p_cell && (p_cell->x >= g.width || p_cell->y >= g.height)) return error(i, "scanned: the cell is off the grid");
  const std::size_t first = i + 1;
  const std::size_t rows = lines.size() - first;
  if (rows != static_cast<std::size_t>(g.height))
    return plan::Error{file, static_cast<int>(lines.size()),
                       std::to_string(rows) + " rows after 'grid', size says " + std::to_string(g.height)};
  g.cells.assign(static_cast<std::size_t>(g.width) * static_cast<std::size_t>(g.height), plan::CellState::Unknown);
  for (std::size_t r = 0; r < rows; ++r) {
    const std::string_view row = lines[first + r];
    if (row.size() != static_cast<std::size_t>(g.width))
      return error(first + r, "row of " + std::to_string(row.size()) + " characters, size says " +
                                  std::to_string(g.width) + " (free cells are spaces: keep trailing spaces)");
    const int y = g.height - 1 - static_cast<int>(r);
    for (int x = 0; x < g.width; ++x) {
      plan::CellState s;
      switch (row[static_cast<std::size_t>(x)]) {
        case '.': s = plan::CellState::Unknown; break;
        case '#': s = plan::CellState::Occupied; break;
        case ' ': s = plan::CellState::Free; break;
        case 'P':
          if (!p_cell || p_cell->x != x || p_cell->y != y)
            return error(first + r, "'P' at column " + std::to_string(x + 1) + ": not the 'scanned' cell");
          s = plan::CellState::Free;
          break;
        default:
          return error(first + r, "character '" + std::string(1, row[static_cast<std::size_t>(x)]) + "' at column " +
                                      std::to_string(x + 1) + " (only '.', '#', ' ', 'P')");
      }
      g.cells[static_cast<std::size_t>(y) * static_cast<std::size_t>(g.width) + static_cast<std::size_t>(x)] = s;
    }
  }
  if (p_cell) {
    const std::string_view row = lines[first + static_cast<std::size_t>(g.height - 1 - p_cell->y)];
    if (row[static_cast<std::size_t>(p_cell->x)] != 'P')
      return error(first + static_cast<std::size_t>(g.height - 1 - p_cell->y), "the 'scanned' cell holds no 'P'");
  }
  g.scanned_from = p_cell;
  return g;
}

std::string place_grid_path(const std::string& dir, const std::string& place) {
  return (dir.empty() ? std::string(".") : dir) + "/" + place + ".txt";
}

plan::Status save_place_grid(const PlaceGrid& grid, const std::string& path) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) return plan::Error{path, 0, "cannot write (" + tmp + ")"};
    const std::string text = place_grid_text(grid);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      return plan::Error{path, 0, "write failed"};
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    return plan::Error{path, 0, "cannot replace the file"};
  }
  return plan::Ok{};
}

plan::Result<PlaceGrid> load_place_grid(const std::string& path) {
  // The largest grid a file may hold (kMaxSide squared, a newline per row) and its header.
  constexpr std::size_t kMaxBytes = static_cast<std::size_t>(kMaxSide) * (kMaxSide + 1) + 4096;
  auto text = plan::read_text_file(path, kMaxBytes);
  if (!text) return text.error();
  return parse_place_grid(*text, path);
}

plan::Result<std::size_t> apply_place_grid(const PlaceGrid& grid, plan::OccupancyMap& map) {
  const double r = map.resolution();
  if (std::abs(grid.cell - r) > 1e-9 * r)
    return plan::Error{grid.place, 0, "cell " + real_text(grid.cell) + " m, the map's is " + real_text(r) + " m"};
  const double fx = (grid.origin.x - map.geometry().origin.x) / r, fy = (grid.origin.y - map.geometry().origin.y) / r;
  const double ox = std::round(fx), oy = std::round(fy);
  if (std::abs(fx - ox) > 1e-6 || std::abs(fy - oy) > 1e-6)
    return plan::Error{grid.place, 0, "origin not on the map's cells (a fraction of a cell off)"};
  std::size_t written = 0;
  for (int y = 0; y < grid.height; ++y)
    for (int x = 0; x < grid.width; ++x) {
      const plan::Cell c{static_cast<int>(ox) + x, static_cast<int>(oy) + y};
      if (!map.contains(c) || map.state(c) != plan::CellState::Unknown) continue;
      switch (grid.at(x, y)) {
        case plan::CellState::Occupied: map.mark_occupied(c); ++written; break;
        case plan::CellState::Free: map.mark_free(c); ++written; break;
        case plan::CellState::Unknown: break;
      }
    }
  return written;
}

}  // namespace robuter::places
