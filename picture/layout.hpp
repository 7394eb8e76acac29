// SPDX-License-Identifier: GPL-3.0-or-later
// What a picture laid out: every title, legend entry, scale bar, axis label and text label with its box.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace robuter::picture {

using Vec2 = Eigen::Vector2d;  // a point or size on the page, px (y down) unless said otherwise

// An axis-aligned rectangle on the page.
struct Rect {
  Vec2 lo = Vec2::Zero();  // top-left corner, px
  Vec2 hi = Vec2::Zero();  // bottom-right corner, px

  // True when the two share some area (touching edges do not count).
  bool overlaps(const Rect& o) const;
  // True when this lies wholly within `o`.
  bool inside(const Rect& o) const;
};

// What a laid-out item is.
enum class Kind { title, legend, scale_bar, axis, label };
std::string_view to_string(Kind k);

// One laid-out item: its kind, its words and where it is.
struct Item {
  Kind kind = Kind::label;  // what it is
  std::string text;         // the words drawn (a legend entry's meaning, a tick's value …)
  Rect box;                 // where it is drawn, px
};

// Everything with words a picture laid out, in drawing order; nothing here overlaps anything else.
struct Layout {
  int width = 0;            // page width, px
  int height = 0;           // page height, px
  std::vector<Item> items;  // title, legend entries, scale bar, tick labels, text labels

  // The whole page as a rectangle, px.
  Rect page() const { return {Vec2::Zero(), Vec2(width, height)}; }
  // True when `r` lies on the page and overlaps no item laid out so far.
  bool free(const Rect& r) const;
  // Items of one kind.
  std::vector<const Item*> of(Kind k) const;
  // The first item of kind `k` whose text contains `words`, or null.
  const Item* find(Kind k, std::string_view words) const;
  // Indices of the first two items that overlap, if any (tests: there must be none).
  std::optional<std::pair<std::size_t, std::size_t>> first_overlap() const;
};

}  // namespace robuter::picture
