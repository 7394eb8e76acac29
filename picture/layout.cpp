// SPDX-License-Identifier: GPL-3.0-or-later
// Rectangle tests and look-ups over the items a picture laid out.
#include "picture/layout.hpp"

namespace robuter::picture {

bool Rect::overlaps(const Rect& o) const {
  return lo.x() < o.hi.x() && o.lo.x() < hi.x() && lo.y() < o.hi.y() && o.lo.y() < hi.y();
}

bool Rect::inside(const Rect& o) const {
  return (lo.array() >= o.lo.array()).all() && (hi.array() <= o.hi.array()).all();
}

std::string_view to_string(Kind k) {
  switch (k) {
    case Kind::title: return "title";
    case Kind::legend: return "legend";
    case Kind::scale_bar: return "scale bar";
    case Kind::axis: return "axis";
    case Kind::label: return "label";
  }
  return "?";
}

bool Layout::free(const Rect& r) const {
  if (!r.inside(page())) return false;
  for (const Item& i : items)
    if (i.box.overlaps(r)) return false;
  return true;
}

std::vector<const Item*> Layout::of(Kind k) const {
  std::vector<const Item*> out;
  for (const Item& i : items)
    if (i.kind == k) out.push_back(&i);
  return out;
}

const Item* Layout::find(Kind k, std::string_view words) const {
  for (const Item& i : items)
    if (i.kind == k && i.text.find(words) != std::string::npos) return &i;
  return nullptr;
}

std::optional<std::pair<std::size_t, std::size_t>> Layout::first_overlap() const {
  for (std::size_t a = 0; a < items.size(); ++a)
    for (std::size_t b = a + 1; b < items.size(); ++b)
      if (items[a].box.overlaps(items[b].box)) return std::pair{a, b};
  return std::nullopt;
}

}  // namespace robuter::picture
